// Animated GIF (giflib): every frame drawn with Cairo into one RGB image, reduced to one global
// palette of 256 colours and stored as the rectangle that changed since the previous frame.
//
// Palette: median cut (Heckbert 1982) over a histogram of colours quantised to 6 bits per
// channel, counted on up to GIF_SAMPLES frames spread over the animation. A box of colours is
// split at the weighted median of its longest side until there are 256 boxes; each palette
// entry is the weighted mean of its box. Pixels map to the nearest entry (squared RGB distance)
// through a table over the 2^18 histogram cells, filled on first use. No dithering: the drawings
// are flat-shaded areas and lines, which dithering would only speckle.
#include <gif_lib.h>
#include <math.h>
#include <string.h>

#include "render_internal.h"

#define GIF_SAMPLES 8
#define HIST_BITS 6
#define HIST_CELLS (1 << (3 * HIST_BITS))
#define PALETTE_SIZE 256

typedef struct gif_out {
    unsigned char *data;
    size_t len, cap;
} gif_out;

static int gif_write_fn(GifFileType *gif, const GifByteType *bytes, int n)
{
    gif_out *o = gif->UserData;
    if (n <= 0) return n;
    if (o->len + (size_t)n > o->cap) {
        size_t cap = o->cap ? o->cap : 65536;
        while (cap < o->len + (size_t)n) cap *= 2;
        o->data = ori__realloc(o->data, cap);
        o->cap = cap;
    }
    memcpy(o->data + o->len, bytes, (size_t)n);
    o->len += (size_t)n;
    return n;
}

static inline int cell_of(uint32_t argb)
{
    int r = (argb >> 16) & 255, g = (argb >> 8) & 255, b = argb & 255;
    int s = 8 - HIST_BITS;
    return ((r >> s) << (2 * HIST_BITS)) | ((g >> s) << HIST_BITS) | (b >> s);
}

// --- median cut -----------------------------------------------------------------------------

typedef struct cbox {
    int first, count; // range in the cell list
    long long weight;
    int lo[3], hi[3];
} cbox;

static int chan(int cell, int c) { return (cell >> ((2 - c) * HIST_BITS)) & ((1 << HIST_BITS) - 1); }

static void box_bounds(cbox *b, const int *cells)
{
    for (int c = 0; c < 3; ++c) {
        b->lo[c] = 1 << HIST_BITS;
        b->hi[c] = -1;
    }
    for (int i = b->first; i < b->first + b->count; ++i)
        for (int c = 0; c < 3; ++c) {
            int v = chan(cells[i], c);
            if (v < b->lo[c]) b->lo[c] = v;
            if (v > b->hi[c]) b->hi[c] = v;
        }
}

// Sort cells[0..n-1] by one channel (counting sort: 2^HIST_BITS values), using tmp (n ints).
static void sort_by_channel(int *cells, int n, int axis, int *tmp)
{
    int count[(1 << HIST_BITS) + 1];
    memset(count, 0, sizeof count);
    for (int i = 0; i < n; ++i) count[chan(cells[i], axis) + 1]++;
    for (int v = 0; v < (1 << HIST_BITS); ++v) count[v + 1] += count[v];
    for (int i = 0; i < n; ++i) tmp[count[chan(cells[i], axis)]++] = cells[i];
    memcpy(cells, tmp, sizeof(int) * (size_t)n);
}

static int median_cut(const uint32_t *hist, ori_rgb *palette)
{
    int ncell = 0;
    for (int i = 0; i < HIST_CELLS; ++i) ncell += hist[i] > 0;
    int *cells = ori__alloc(sizeof(int) * (size_t)(ncell + 1));
    int *tmp = ori__alloc(sizeof(int) * (size_t)(ncell + 1));
    ncell = 0;
    long long total = 0;
    for (int i = 0; i < HIST_CELLS; ++i)
        if (hist[i]) {
            cells[ncell++] = i;
            total += hist[i];
        }
    cbox boxes[PALETTE_SIZE];
    int nb = 0;
    if (ncell > 0) {
        boxes[0].first = 0;
        boxes[0].count = ncell;
        boxes[0].weight = total;
        box_bounds(&boxes[0], cells);
        nb = 1;
    }
    while (nb < PALETTE_SIZE) {
        // Split the box with the largest (side × weight) that has more than one cell.
        int best = -1;
        double score = 0.0;
        for (int i = 0; i < nb; ++i) {
            if (boxes[i].count < 2) continue;
            int side = 0;
            for (int c = 0; c < 3; ++c)
                if (boxes[i].hi[c] - boxes[i].lo[c] > side) side = boxes[i].hi[c] - boxes[i].lo[c];
            double s = (double)side * (double)boxes[i].weight;
            if (s > score) {
                score = s;
                best = i;
            }
        }
        if (best < 0) break;
        cbox *b = &boxes[best];
        int axis = 0;
        for (int c = 1; c < 3; ++c)
            if (b->hi[c] - b->lo[c] > b->hi[axis] - b->lo[axis]) axis = c;
        sort_by_channel(cells + b->first, b->count, axis, tmp);
        long long half = b->weight / 2, acc = 0;
        int k = 0;
        while (k < b->count - 1 && acc + hist[cells[b->first + k]] <= half) acc += hist[cells[b->first + k++]];
        if (k == 0) {
            acc = hist[cells[b->first]];
            k = 1;
        }
        cbox nbx;
        nbx.first = b->first + k;
        nbx.count = b->count - k;
        nbx.weight = b->weight - acc;
        b->count = k;
        b->weight = acc;
        box_bounds(b, cells);
        box_bounds(&nbx, cells);
        boxes[nb++] = nbx;
    }
    double unit = 255.0 / ((1 << HIST_BITS) - 1);
    for (int i = 0; i < nb; ++i) {
        double s[3] = {0, 0, 0};
        for (int j = boxes[i].first; j < boxes[i].first + boxes[i].count; ++j)
            for (int c = 0; c < 3; ++c) s[c] += (double)hist[cells[j]] * chan(cells[j], c) * unit;
        double w = (double)boxes[i].weight;
        palette[i].r = s[0] / w;
        palette[i].g = s[1] / w;
        palette[i].b = s[2] / w;
    }
    ori__free(cells);
    ori__free(tmp);
    return nb;
}

static unsigned char nearest(const ori_rgb *pal, int n, int cell)
{
    double unit = 255.0 / ((1 << HIST_BITS) - 1);
    double r = chan(cell, 0) * unit, g = chan(cell, 1) * unit, b = chan(cell, 2) * unit;
    int best = 0;
    double bd = INFINITY;
    for (int i = 0; i < n; ++i) {
        double d = (pal[i].r - r) * (pal[i].r - r) + (pal[i].g - g) * (pal[i].g - g) + (pal[i].b - b) * (pal[i].b - b);
        if (d < bd) {
            bd = d;
            best = i;
        }
    }
    return (unsigned char)best;
}

// --- the animation --------------------------------------------------------------------------

ori_gif_def ori_default_gif_def(void)
{
    ori_gif_def d;
    memset(&d, 0, sizeof d);
    d.render = ori_default_render_def();
    d.render.view = ORI_RENDER_3D;
    d.frame_count = 0;
    d.frame = NULL;
    d.user = NULL;
    d.fps = 15.0;
    d.hold_last_s = 1.0;
    d.loop = true;
    d.progress = NULL;
    d.progress_user = NULL;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

typedef struct gif_job {
    const ori_gif_def *def;
    ori_mesh *mesh;
    ori_camera cam;
    ori_v3 lo, hi;
    cairo_surface_t *surface;
    cairo_surface_t *texture;
    uint32_t *pixels;
    int stride_px;
    int done, total; // progress
} gif_job;

static ori_status pose_frame(gif_job *j, int index, ori_state_view *sv, ori_error *error)
{
    ori_status st = j->def->frame(index, sv, j->def->user, error);
    if (st != ORI_OK) return st;
    if (!j->mesh) return ori_mesh_create(sv, &j->mesh, error);
    if (ori_pattern_vertex_count(sv->pattern) != j->mesh->vertex_count ||
        ori_pattern_face_count(sv->pattern) != j->mesh->face_count)
        return ori__fail(error, ORI_ERR_ARGUMENT, "frame %d is not a state of the first frame's pattern", index);
    const ori_v3 *pos = sv->positions;
    if (!pos) {
        // A folded form drawn as it is.
        ori_v3 *tmp = ori__alloc(sizeof(ori_v3) * (size_t)(j->mesh->vertex_count + 1));
        for (int v = 0; v < j->mesh->vertex_count; ++v) tmp[v] = ori_pattern_vertex(sv->pattern, v);
        st = ori_mesh_set_pose(j->mesh, tmp, sv->fold_angles_rad, error);
        ori__free(tmp);
        return st;
    }
    return ori_mesh_set_pose(j->mesh, pos, sv->fold_angles_rad, error);
}

static ori_status draw_frame(gif_job *j, int index, ori_error *error)
{
    ori_state_view sv;
    ori_status st = pose_frame(j, index, &sv, error);
    if (st != ORI_OK) return st;
    ori_render_def rd = j->def->render;
    if (j->def->frame_values) { // this frame's values under the animation's one colour bar
        const double *fv = NULL, *ev = NULL;
        st = j->def->frame_values(index, &fv, &ev, j->def->user, error);
        if (st != ORI_OK) return st;
        if ((fv == NULL) == (ev == NULL))
            return ori__fail(error, ORI_ERR_ARGUMENT, "values: frame %d gives %s", index,
                             fv ? "both face and edge values" : "no values");
        rd.values.face_values = fv;
        rd.values.edge_values = ev;
    }
    cairo_t *cr = cairo_create(j->surface);
    st = ori__draw(cr, j->mesh, sv.pattern, &rd, &j->cam, j->texture, &j->lo, &j->hi, error);
    cairo_status_t cs = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(j->surface);
    if (st == ORI_OK && cs != CAIRO_STATUS_SUCCESS)
        st = ori__fail(error, ORI_ERR_INTERNAL, "drawing failed: %s", cairo_status_to_string(cs));
    if (st == ORI_OK && j->def->progress) {
        j->done++;
        if (!j->def->progress((double)j->done / j->total, j->def->progress_user))
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
    return st;
}

static ori_status gif_fail(ori_error *error, int code)
{
    return ori__fail(error, ORI_ERR_INTERNAL, "GIF encoding failed: %s", GifErrorString(code));
}

ori_status ori_gif_write(const ori_gif_def *def, void **data, size_t *size, ori_error *error)
{
    ORI_ASSERT(def && data && size);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE && def->render.internal_value == ORI__DEF_COOKIE);
    *data = NULL;
    *size = 0;
    ori_status st = ori__render_check_size(&def->render, error);
    if (st != ORI_OK) return st;
    if (def->frame_count < 1 || !def->frame) return ori__fail(error, ORI_ERR_ARGUMENT, "an animation needs frames");
    if (!(def->fps >= 1.0 && def->fps <= 100.0))
        return ori__fail(error, ORI_ERR_ARGUMENT, "frame rate %g is outside 1 to 100 per second", def->fps);
    if (!(def->hold_last_s >= 0.0) || !isfinite(def->hold_last_s))
        return ori__fail(error, ORI_ERR_ARGUMENT, "the last frame's hold must be a finite time >= 0");
    if (def->render.view != ORI_RENDER_3D)
        return ori__fail(error, ORI_ERR_ARGUMENT, "an animation shows the 3D view");
    if (ori__value_map_active(&def->render.values))
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "values: an animation takes its values frame by frame (frame_values), not as one state's arrays");
    if (def->frame_values && (!isfinite(def->render.values.min) || !isfinite(def->render.values.max) ||
                              def->render.values.min > def->render.values.max))
        return ori__fail(error, ORI_ERR_ARGUMENT, "values: the colour bar's range needs finite min <= max (got %g, %g)",
                         def->render.values.min, def->render.values.max);
    int W = def->render.width, H = def->render.height, N = def->frame_count;
    gif_job j;
    memset(&j, 0, sizeof j);
    j.def = def;
    int samples = N < GIF_SAMPLES ? N : GIF_SAMPLES;
    j.total = N + samples;
    st = ori__texture_load(&def->render, &j.texture, error);
    if (st != ORI_OK) return st;

    // Pass 0: the box of every frame (the grid and a fitted camera must not jump).
    ori_state_view sv;
    ori_v3 *pts = NULL;
    int pts_cap = 0;
    for (int i = 0; i < N && st == ORI_OK; ++i) {
        st = pose_frame(&j, i, &sv, error);
        if (st != ORI_OK) break;
        ori_v3 lo, hi;
        ori_mesh_bounds(j.mesh, &lo, &hi);
        if (i == 0) {
            j.lo = lo;
            j.hi = hi;
        } else {
            j.lo = ori_v3_make(fmin(j.lo.x, lo.x), fmin(j.lo.y, lo.y), fmin(j.lo.z, lo.z));
            j.hi = ori_v3_make(fmax(j.hi.x, hi.x), fmax(j.hi.y, hi.y), fmax(j.hi.z, hi.z));
        }
    }
    j.cam = def->render.camera;
    if (st == ORI_OK && def->render.fit_camera) {
        ori__camera_fit_box(&j.cam, j.lo, j.hi);
        double ext[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
        for (int i = 0; i < N && st == ORI_OK; ++i) {
            st = pose_frame(&j, i, &sv, error);
            if (st != ORI_OK) break;
            ORI__RESERVE(pts, pts_cap, j.mesh->vertex_count + 4);
            int n = ori__render_scene_points(j.mesh, &def->render, &j.lo, &j.hi, pts);
            ori__camera_extents_add(&j.cam, pts, n, ext);
        }
        ori__camera_fit_extents(&j.cam, ext, W, H, 0.05, 0.5 * ori_v3_norm(ori_v3_sub(j.hi, j.lo)));
    }
    ori__free(pts);
    if (st != ORI_OK) {
        ori_mesh_destroy(j.mesh);
        if (j.texture) cairo_surface_destroy(j.texture);
        return st;
    }

    int stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, W);
    j.stride_px = stride / 4;
    j.pixels = ori__alloc((size_t)stride * (size_t)H);
    j.surface = cairo_image_surface_create_for_data((unsigned char *)j.pixels, CAIRO_FORMAT_RGB24, W, H, stride);

    // Pass 1: the palette from sample frames.
    uint32_t *hist = ori__calloc(HIST_CELLS, sizeof(uint32_t));
    for (int s = 0; s < samples && st == ORI_OK; ++s) {
        int i = samples == 1 ? 0 : (int)lround((double)s * (N - 1) / (samples - 1));
        st = draw_frame(&j, i, error);
        for (int y = 0; y < H && st == ORI_OK; ++y)
            for (int x = 0; x < W; ++x) hist[cell_of(j.pixels[y * j.stride_px + x])]++;
    }
    ori_rgb pal[PALETTE_SIZE]; // components 0 … 255
    int npal = st == ORI_OK ? median_cut(hist, pal) : 0;
    if (npal == 0) {
        pal[0] = def->render.background;
        pal[0].r *= 255.0;
        pal[0].g *= 255.0;
        pal[0].b *= 255.0;
        npal = 1;
    }
    short *lut = ori__alloc(sizeof(short) * HIST_CELLS);
    for (int i = 0; i < HIST_CELLS; ++i) lut[i] = -1;

    // Pass 2: encode.
    gif_out out = {NULL, 0, 0};
    int gerr = 0;
    GifFileType *gif = NULL;
    ColorMapObject *cmap = NULL;
    unsigned char *cur = NULL, *prev = NULL;
    if (st == ORI_OK) {
        gif = EGifOpen(&out, gif_write_fn, &gerr);
        if (!gif) st = gif_fail(error, gerr);
    }
    if (st == ORI_OK) {
        cmap = GifMakeMapObject(PALETTE_SIZE, NULL);
        for (int i = 0; i < PALETTE_SIZE; ++i) {
            ori_rgb c = pal[i < npal ? i : 0];
            cmap->Colors[i].Red = (GifByteType)lround(fmin(255.0, fmax(0.0, c.r)));
            cmap->Colors[i].Green = (GifByteType)lround(fmin(255.0, fmax(0.0, c.g)));
            cmap->Colors[i].Blue = (GifByteType)lround(fmin(255.0, fmax(0.0, c.b)));
        }
        EGifSetGifVersion(gif, true);
        if (EGifPutScreenDesc(gif, W, H, 8, 0, cmap) == GIF_ERROR) st = gif_fail(error, gif->Error);
    }
    if (st == ORI_OK && def->loop) {
        // NETSCAPE2.0 application extension: loop forever.
        unsigned char app[11] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
        unsigned char sub[3] = {1, 0, 0};
        if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
            EGifPutExtensionBlock(gif, 11, app) == GIF_ERROR || EGifPutExtensionBlock(gif, 3, sub) == GIF_ERROR ||
            EGifPutExtensionTrailer(gif) == GIF_ERROR)
            st = gif_fail(error, gif->Error);
    }
    cur = ori__alloc((size_t)W * (size_t)H);
    prev = ori__alloc((size_t)W * (size_t)H);
    for (int i = 0; i < N && st == ORI_OK; ++i) {
        st = draw_frame(&j, i, error);
        if (st != ORI_OK) break;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int c = cell_of(j.pixels[y * j.stride_px + x]);
                if (lut[c] < 0) lut[c] = nearest(pal, npal, c);
                cur[y * W + x] = (unsigned char)lut[c];
            }
        // The rectangle that changed (the whole image at first).
        int x0 = 0, y0 = 0, x1 = W - 1, y1 = H - 1;
        if (i > 0) {
            x0 = W;
            y0 = H;
            x1 = -1;
            y1 = -1;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x)
                    if (cur[y * W + x] != prev[y * W + x]) {
                        if (x < x0) x0 = x;
                        if (x > x1) x1 = x;
                        if (y < y0) y0 = y;
                        if (y > y1) y1 = y;
                    }
            if (x1 < 0) x0 = y0 = x1 = y1 = 0; // nothing changed: one pixel keeps the timing
        }
        // Delays in 1/100 s, rounded cumulatively so that the average rate is exact.
        int delay = (int)(lround(100.0 * (i + 1) / def->fps) - lround(100.0 * i / def->fps));
        if (i == N - 1) delay += (int)lround(100.0 * def->hold_last_s);
        GraphicsControlBlock gcb = {DISPOSE_DO_NOT, false, delay, NO_TRANSPARENT_COLOR};
        GifByteType ext[4];
        size_t elen = EGifGCBToExtension(&gcb, ext);
        if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, (int)elen, ext) == GIF_ERROR ||
            EGifPutImageDesc(gif, x0, y0, x1 - x0 + 1, y1 - y0 + 1, false, NULL) == GIF_ERROR) {
            st = gif_fail(error, gif->Error);
            break;
        }
        for (int y = y0; y <= y1; ++y)
            if (EGifPutLine(gif, cur + (size_t)y * W + x0, x1 - x0 + 1) == GIF_ERROR) {
                st = gif_fail(error, gif->Error);
                break;
            }
        unsigned char *t = prev;
        prev = cur;
        cur = t;
    }
    if (gif) {
        int cerr = 0;
        if (EGifCloseFile(gif, &cerr) == GIF_ERROR && st == ORI_OK) st = gif_fail(error, cerr);
    }
    GifFreeMapObject(cmap);
    ori__free(cur);
    ori__free(prev);
    ori__free(lut);
    ori__free(hist);
    cairo_surface_destroy(j.surface);
    ori__free(j.pixels);
    if (j.texture) cairo_surface_destroy(j.texture);
    ori_mesh_destroy(j.mesh);
    if (st != ORI_OK) {
        ori__free(out.data);
        return st;
    }
    *data = out.data;
    *size = out.len;
    return ORI_OK;
}
