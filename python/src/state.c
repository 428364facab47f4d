// One state of a pattern (its world vertex positions and fold angles) drawn, exported as a mesh,
// checked for self-collision; a motion's states as an animated GIF or an animated glTF.
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

// The drawing options shared by render and animate (cli/render_args.c's, in radians).
typedef struct draw_opts {
    const char *view, *camera, *front, *back, *background;
    double yaw, pitch, roll;
    int width, height;
    int perspective, edges, grid, labels, shading;
    PyObject *texture; // bytes (a PNG) or None
    PyObject *face_orders;
} draw_opts;

static bool read_colour(const char *text, ori_rgb *out, const char *what)
{
    if (!text) return true;
    if (!ori_rgb_parse(text, out)) {
        PyErr_Format(PyExc_ValueError, "%s needs a colour (#rrggbb, #rgb or a name such as orange), got '%s'", what, text);
        return false;
    }
    return true;
}

// Fill a render def; *orders (a kept int array or NULL) holds the faceOrders for the call.
static bool render_def_of(const draw_opts *o, ori_render_def *d, PyArrayObject **orders)
{
    *orders = NULL;
    *d = ori_default_render_def();
    if (strcmp(o->view, "3d") == 0) d->view = ORI_RENDER_3D;
    else if (strcmp(o->view, "cp") == 0) d->view = ORI_RENDER_CREASES;
    else {
        PyErr_Format(PyExc_ValueError, "view is cp or 3d, got '%s'", o->view);
        return false;
    }
    static const char *const names[] = {"iso", "top", "front", "side", "bottom"};
    static const ori_camera_preset_kind kinds[] = {ORI_CAMERA_ISO, ORI_CAMERA_TOP, ORI_CAMERA_FRONT, ORI_CAMERA_SIDE,
                                                   ORI_CAMERA_BOTTOM};
    int k = 0;
    while (k < 5 && strcmp(o->camera, names[k]) != 0) k++;
    if (k == 5) {
        PyErr_Format(PyExc_ValueError, "camera is iso, top, front, side or bottom, got '%s'", o->camera);
        return false;
    }
    if (o->width < 1 || o->height < 1 || o->width > ORI_RENDER_MAX_SIZE || o->height > ORI_RENDER_MAX_SIZE) {
        PyErr_Format(PyExc_ValueError, "size needs width and height from 1 to %d, got %d x %d", ORI_RENDER_MAX_SIZE,
                     o->width, o->height);
        return false;
    }
    d->width = o->width;
    d->height = o->height;
    d->camera = ori_camera_preset(kinds[k], o->yaw, o->pitch, o->roll);
    d->camera.perspective = o->perspective;
    d->fit_camera = true;
    d->all_edges = o->edges;
    d->grid = o->grid;
    d->labels = o->labels;
    d->shading = o->shading;
    if (!read_colour(o->front, &d->front, "front") || !read_colour(o->back, &d->back, "back") ||
        !read_colour(o->background, &d->background, "background"))
        return false;
    if (o->texture && o->texture != Py_None) {
        if (!PyBytes_Check(o->texture)) {
            PyErr_SetString(PyExc_TypeError, "texture must be the bytes of a PNG image");
            return false;
        }
        d->texture_png = PyBytes_AS_STRING(o->texture);
        d->texture_size = (size_t)PyBytes_GET_SIZE(o->texture);
    }
    if (o->face_orders && o->face_orders != Py_None) {
        *orders = (PyArrayObject *)PyArray_FROMANY(o->face_orders, NPY_INT, 2, 2, NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST);
        if (!*orders || PyArray_DIM(*orders, 1) != 3 || PyArray_DIM(*orders, 0) > INT_MAX) {
            Py_CLEAR(*orders);
            PyErr_SetString(PyExc_ValueError, "face_orders must be an (n, 3) array of FOLD faceOrders triples");
            return false;
        }
        d->face_orders = PyArray_DATA(*orders);
        d->face_order_count = (int)PyArray_DIM(*orders, 0);
    }
    return true;
}

#define DRAW_KWLIST "view", "camera", "yaw_rad", "pitch_rad", "roll_rad", "width", "height", "perspective", "edges", \
                    "grid", "labels", "shading", "front", "back", "background", "texture", "face_orders"
#define DRAW_FORMAT "ssdddiipppppzzzOO"
#define DRAW_ARGS(o) &o.view, &o.camera, &o.yaw, &o.pitch, &o.roll, &o.width, &o.height, &o.perspective, &o.edges, \
                     &o.grid, &o.labels, &o.shading, &o.front, &o.back, &o.background, &o.texture, &o.face_orders

static void draw_opts_init(draw_opts *o)
{
    memset(o, 0, sizeof *o);
    o->view = "3d";
    o->camera = "iso";
    o->width = 800;
    o->height = 600;
    o->shading = 1;
}

// Bytes out of a library buffer, or the file written: None.
static PyObject *bytes_or_none(void *data, size_t size)
{
    PyObject *b = PyBytes_FromStringAndSize(data, (Py_ssize_t)size);
    ori_buffer_free(data);
    return b;
}

// render(pattern, positions, angles, path, format, **drawing): an image of the state.
static PyObject *py_render(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "positions", "angles", "path", "format", DRAW_KWLIST, NULL};
    PyObject *pobj, *positions = Py_None, *angles = Py_None, *path = Py_None;
    const char *format = NULL;
    draw_opts o;
    draw_opts_init(&o);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!|OOOz" DRAW_FORMAT, kwlist, &ori_py_PatternType, &pobj, &positions, &angles,
                                     &path, &format, DRAW_ARGS(o)))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    ori_render_def d;
    PyArrayObject *orders;
    if (!render_def_of(&o, &d, &orders)) return NULL;
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, angles, positions)) {
        Py_XDECREF(orders);
        return NULL;
    }
    ori_state_view view = {pat->p, s.positions, s.angles};
    PyObject *result = NULL, *path_b = NULL;
    ori_error err;
    ori_status st;
    if (format) {
        static const char *const fmts[] = {"svg", "pdf", "png"};
        static const ori_image_format kinds[] = {ORI_IMAGE_SVG, ORI_IMAGE_PDF, ORI_IMAGE_PNG};
        int k = 0;
        while (k < 3 && strcmp(format, fmts[k]) != 0) k++;
        if (k == 3) {
            PyErr_Format(PyExc_ValueError, "format is svg, pdf or png, got '%s'", format);
            goto done;
        }
        d.format = kinds[k];
    }
    if (path != Py_None) {
        if (!PyUnicode_FSConverter(path, &path_b)) goto done;
        const char *p = PyBytes_AS_STRING(path_b);
        if (!format) d.format = ori_image_format_from_path(p);
        if (d.format == ORI_IMAGE_UNKNOWN) {
            PyErr_Format(PyExc_ValueError, "%s: the image format is .svg, .pdf or .png", p);
            goto done;
        }
        Py_BEGIN_ALLOW_THREADS
        st = ori_render_file(&view, &d, p, &err);
        Py_END_ALLOW_THREADS
        if (st != ORI_OK) ori_py_raise(p, &err);
        else result = Py_NewRef(Py_None);
    } else {
        void *data = NULL;
        size_t size = 0;
        Py_BEGIN_ALLOW_THREADS
        st = ori_render_image(&view, &d, &data, &size, &err);
        Py_END_ALLOW_THREADS
        if (st != ORI_OK) ori_py_raise(ori_py_pattern_source(pat), &err);
        else result = bytes_or_none(data, size);
    }
done:
    Py_XDECREF(path_b);
    Py_XDECREF(orders);
    ori_py_state_free(&s);
    return result;
}

static bool read_mesh_format(const char *format, ori_mesh_format *out)
{
    static const char *const fmts[] = {"obj", "stl", "ply", "gltf", "glb"};
    static const ori_mesh_format kinds[] = {ORI_MESH_OBJ, ORI_MESH_STL, ORI_MESH_PLY, ORI_MESH_GLTF, ORI_MESH_GLB};
    for (int k = 0; k < 5; ++k)
        if (strcmp(format, fmts[k]) == 0) {
            *out = kinds[k];
            return true;
        }
    PyErr_Format(PyExc_ValueError, "format is obj, stl, ply, gltf or glb, got '%s'", format);
    return false;
}

// export_mesh(pattern, positions, angles, path, format, thickness, times, poses): a mesh of the
// state, or an animated glTF/GLB (times: K seconds; poses: (K, F, 3, 4) [R | t] per face).
static PyObject *py_export_mesh(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "positions", "angles", "path", "format", "thickness", "times", "poses", NULL};
    PyObject *pobj, *positions = Py_None, *angles = Py_None, *path = Py_None, *times = Py_None, *poses = Py_None;
    const char *format = NULL;
    double thickness = 0.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!|OOOzdOO", kwlist, &ori_py_PatternType, &pobj, &positions, &angles, &path,
                                     &format, &thickness, &times, &poses))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    ori_export_def d = ori_default_export_def();
    if (format && !read_mesh_format(format, &d.format)) return NULL;
    d.thickness = thickness;
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, angles, positions)) return NULL;
    PyArrayObject *ta = NULL, *pa = NULL;
    ori_rigid *kp = NULL;
    PyObject *result = NULL, *path_b = NULL;
    ori_mesh *mesh = NULL;
    int F = ori_pattern_face_count(pat->p);
    if (times != Py_None) {
        ta = (PyArrayObject *)PyArray_FROMANY(times, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY);
        npy_intp K = ta ? PyArray_DIM(ta, 0) : 0;
        pa = ta ? (PyArrayObject *)PyArray_FROMANY(poses, NPY_DOUBLE, 4, 4, NPY_ARRAY_IN_ARRAY) : NULL;
        if (!pa || K < 1 || K > INT_MAX || PyArray_DIM(pa, 0) != K || PyArray_DIM(pa, 1) != F || PyArray_DIM(pa, 2) != 3 ||
            PyArray_DIM(pa, 3) != 4) {
            PyErr_Format(PyExc_ValueError, "an animation needs times (K,) and poses (K, %d, 3, 4)", F);
            goto done;
        }
        kp = PyMem_Malloc(sizeof(ori_rigid) * (size_t)(K * F + 1));
        if (!kp) {
            PyErr_NoMemory();
            goto done;
        }
        const double *src = PyArray_DATA(pa);
        for (npy_intp i = 0; i < K * F; ++i) {
            const double *q = src + 12 * i;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) kp[i].r.m[r][c] = q[4 * r + c];
            kp[i].t = ori_v3_make(q[3], q[7], q[11]);
        }
        d.keyframe_count = (int)K;
        d.keyframe_times_s = PyArray_DATA(ta);
        d.keyframe_poses = kp;
    }
    ori_state_view view = {pat->p, s.positions, s.angles};
    ori_error err;
    ori_status st;
    if (path != Py_None && !PyUnicode_FSConverter(path, &path_b)) goto done;
    const char *p = path_b ? PyBytes_AS_STRING(path_b) : NULL;
    if (p && !format) {
        d.format = ori_mesh_format_from_path(p);
        if (d.format == ORI_MESH_UNKNOWN) {
            PyErr_Format(PyExc_ValueError, "%s: the mesh format is .obj, .stl, .ply, .gltf or .glb", p);
            goto done;
        }
    }
    void *data = NULL;
    size_t size = 0;
    Py_BEGIN_ALLOW_THREADS
    st = ori_mesh_create(&view, &mesh, &err);
    if (st == ORI_OK) st = p ? ori_mesh_export_file(mesh, &d, p, &err) : ori_mesh_export(mesh, &d, &data, &size, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) ori_py_raise(p ? p : ori_py_pattern_source(pat), &err);
    else result = p ? Py_NewRef(Py_None) : bytes_or_none(data, size);
done:
    ori_mesh_destroy(mesh);
    PyMem_Free(kp);
    Py_XDECREF(ta);
    Py_XDECREF(pa);
    Py_XDECREF(path_b);
    ori_py_state_free(&s);
    return result;
}

// The frames of an animation: positions (K, V, 3) and angles (K, E) or None.
typedef struct gif_frames {
    const ori_pattern *p;
    const ori_v3 *positions;
    const double *angles;
    int V, E;
} gif_frames;

static ori_status gif_frame(int k, ori_state_view *out, void *user, ori_error *error)
{
    const gif_frames *g = user;
    (void)error;
    out->pattern = g->p;
    out->positions = g->positions + (size_t)k * (size_t)g->V;
    out->fold_angles_rad = g->angles ? g->angles + (size_t)k * (size_t)g->E : NULL;
    return ORI_OK;
}

// animate(pattern, positions, angles, path, fps, hold, loop, progress, **drawing): a GIF.
static PyObject *py_animate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "positions", "angles", "path", "fps", "hold", "loop", "progress", DRAW_KWLIST, NULL};
    PyObject *pobj, *positions, *angles = Py_None, *path = Py_None, *progress = Py_None;
    double fps = 15.0, hold = 1.0;
    int loop = 1;
    draw_opts o;
    draw_opts_init(&o);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!O|OOddpO" DRAW_FORMAT, kwlist, &ori_py_PatternType, &pobj, &positions,
                                     &angles, &path, &fps, &hold, &loop, &progress, DRAW_ARGS(o)))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    int V = ori_pattern_vertex_count(pat->p), E = ori_pattern_edge_count(pat->p);
    PyArrayObject *pa = (PyArrayObject *)PyArray_FROMANY(positions, NPY_DOUBLE, 3, 3, NPY_ARRAY_IN_ARRAY);
    if (!pa || PyArray_DIM(pa, 0) < 1 || PyArray_DIM(pa, 0) > INT_MAX || PyArray_DIM(pa, 1) != V || PyArray_DIM(pa, 2) != 3) {
        Py_XDECREF(pa);
        return PyErr_Format(PyExc_ValueError, "positions must have shape (frames, %d, 3)", V);
    }
    int K = (int)PyArray_DIM(pa, 0);
    PyArrayObject *aa = NULL;
    if (angles != Py_None) {
        aa = (PyArrayObject *)PyArray_FROMANY(angles, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
        if (!aa || PyArray_DIM(aa, 0) != K || PyArray_DIM(aa, 1) != E) {
            Py_XDECREF(aa);
            Py_DECREF(pa);
            return PyErr_Format(PyExc_ValueError, "angles must have shape (%d, %d)", K, E);
        }
    }
    ori_gif_def g = ori_default_gif_def();
    PyArrayObject *orders;
    PyObject *result = NULL, *path_b = NULL;
    if (!render_def_of(&o, &g.render, &orders)) goto done;
    g.render.view = ORI_RENDER_3D;
    gif_frames fr = {pat->p, PyArray_DATA(pa), aa ? PyArray_DATA(aa) : NULL, V, E};
    g.frame_count = K;
    g.frame = gif_frame;
    g.user = &fr;
    g.fps = fps;
    g.hold_last_s = hold;
    g.loop = loop;
    g.progress = ori_py_progress_fn;
    g.progress_user = &pp;
    if (path != Py_None && !PyUnicode_FSConverter(path, &path_b)) goto done;
    const char *p = path_b ? PyBytes_AS_STRING(path_b) : NULL;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_gif_write(&g, &data, &size, &err);
    if (st == ORI_OK && p) st = ori_file_write_atomic(p, data, size, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        ori_buffer_free(data);
        ori_py_solve_failed(&pp, p ? p : ori_py_pattern_source(pat), &err);
    } else if (p) {
        ori_buffer_free(data);
        result = Py_NewRef(Py_None);
    } else {
        result = bytes_or_none(data, size);
    }
done:
    Py_XDECREF(orders);
    Py_XDECREF(path_b);
    Py_XDECREF(aa);
    Py_DECREF(pa);
    return result;
}

// collide(pattern, positions, clearance): self-collision of one state.
static PyObject *py_collide(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "positions", "clearance", NULL};
    PyObject *pobj, *positions = Py_None;
    double clearance = 0.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!|Od", kwlist, &ori_py_PatternType, &pobj, &positions, &clearance))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    const char *src = ori_py_pattern_source(pat);
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, Py_None, positions)) return NULL;
    ori_collider *c = ori_py_collider(pat, clearance);
    if (!c) {
        ori_py_state_free(&s);
        return NULL;
    }
    ori_error err;
    int V = ori_pattern_vertex_count(pat->p);
    ori_v3 *own = NULL;
    const ori_v3 *pos = s.positions;
    if (!pos) { // the pattern's own coordinates (a folded form, or the flat sheet)
        own = PyMem_Malloc(sizeof(ori_v3) * (size_t)(V + 1));
        if (!own) {
            ori_collider_destroy(c);
            ori_py_state_free(&s);
            return PyErr_NoMemory();
        }
        for (int v = 0; v < V; ++v) own[v] = ori_pattern_vertex(pat->p, v);
        pos = own;
    }
    ori_collision_result r;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_collider_check(c, pos, &r, &err);
    Py_END_ALLOW_THREADS
    PyObject *result = NULL;
    if (st != ORI_OK) {
        ori_py_raise(src, &err);
    } else {
        int n = ori_collider_contact_count(c);
        PyObject *contacts = PyList_New(n);
        for (int i = 0; contacts && i < n; ++i) {
            ori_contact k = ori_collider_contact(c, i);
            PyObject *o = ori_py_contact_dict(&k);
            if (!o) {
                Py_CLEAR(contacts);
                break;
            }
            PyList_SET_ITEM(contacts, i, o);
        }
        if (contacts)
            result = ori_py_dict(
                "collides", PyBool_FromLong(r.collides), "penetrating", PyLong_FromLong(r.penetrating), "touching",
                PyLong_FromLong(r.touching), "near", PyLong_FromLong(r.near), "min_clearance", PyFloat_FromDouble(r.min_clearance),
                "clearance_faces",
                r.clearance_faces[0] == ORI_NULL_INDEX ? Py_NewRef(Py_None)
                                                       : Py_BuildValue("(ii)", r.clearance_faces[0], r.clearance_faces[1]),
                "witness", r.has_witness ? ori_py_v3(r.witness) : Py_NewRef(Py_None), "tolerance",
                PyFloat_FromDouble(r.tolerance), "contacts", contacts, NULL);
    }
    PyMem_Free(own);
    ori_collider_destroy(c);
    ori_py_state_free(&s);
    return result;
}

#define KW (PyCFunction)(void (*)(void))
PyMethodDef ori_py_state_functions[] = {
    {"render", KW py_render, METH_VARARGS | METH_KEYWORDS, "An image (SVG, PDF, PNG) of a state: bytes, or written to path."},
    {"export_mesh", KW py_export_mesh, METH_VARARGS | METH_KEYWORDS, "A mesh (OBJ, STL, PLY, glTF, GLB) of a state."},
    {"animate", KW py_animate, METH_VARARGS | METH_KEYWORDS, "An animated GIF of states."},
    {"collide", KW py_collide, METH_VARARGS | METH_KEYWORDS, "Self-collision of one state."},
    {NULL, NULL, 0, NULL},
};
