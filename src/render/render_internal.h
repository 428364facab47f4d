// Private pieces of src/render shared with the mesh writers of src/io: the posed mesh's
// layout, the thick solid, the depth order of faces, and the Cairo drawing entry used by the
// image and GIF writers.
#ifndef ORI_RENDER_INTERNAL_H
#define ORI_RENDER_INTERNAL_H

#include <orikin/render.h>

#include <cairo.h>

#include "../core/core_internal.h"

struct ori_mesh {
    int vertex_count, edge_count, face_count, tri_count;
    bool has_flat;           // the pattern is a flat crease pattern: ref is the flat sheet
    ori_v3 *ref;             // reference positions (flat sheet, z = 0, or the first pose)
    ori_v3 *pos;             // current world positions
    int *face_start;         // face_count + 1 offsets into face_verts / face_side_edge
    int *face_verts;         // vertex cycles, counter-clockwise seen from the front
    int *face_side_edge;     // FOLD edge of side k (vertex k → k + 1) or -1
    int *face_tri_start;     // face_count + 1 offsets into tris
    ori_mesh_triangle *tris; // grouped by face
    ori_v3 *normal;          // unit front normal per face, current pose
    signed char *fold_sign;  // per face: +1 when face_verts keeps the FOLD faces_vertices order, −1 when
                             // reversed (a flat face listed clockwise); FOLD's normal is fold_sign · normal
    int (*edge_v)[2];        // edge endpoints
    int (*edge_face)[2];     // face on the left / right of v0 → v1, or -1
    ori_assignment *assign;  // edge assignments
    double *angle;           // current fold angle per edge (radians), for layer stacking
    double *pattern_angle;   // the pattern's fold angles
    double ref_diag;         // bounding-box diagonal of ref (1 when degenerate)
};

// Copy n fold angles (or the pattern's when NULL) into the mesh's current angles.
void ori__mesh_set_angles(ori_mesh *m, const double *fold_angles_rad);

// --- camera fitting in steps (camera.c), for fitting to every frame of an animation ---------

// Aim at the centre of the box lo–hi (perspective distance from its radius); scale 1, no offset.
void ori__camera_fit_box(ori_camera *c, ori_v3 lo, ori_v3 hi);
// Grow ext = {x0, x1, y0, y1} by the images of points under c.
void ori__camera_extents_add(const ori_camera *c, const ori_v3 *points, int count, double ext[4]);
// Scale and centre c so that ext (measured at scale 1, no offset) fits a width × height image.
void ori__camera_fit_extents(ori_camera *c, const double ext[4], int width, int height, double margin_rel,
                             double radius);

// --- thick solid (solid.c) -----------------------------------------------------------------

// Offset thick panels around the posed sheet (docs/render.md): one closed prism per panel (a flat
// region), on the back side of the sheet, panels in one plane stacked by layer (face_orders:
// FOLD faceOrders triples checked by ori__face_orders_check, or NULL). Triangles are
// counter-clockwise seen from outside.
typedef enum ori__solid_part { ORI__SOLID_TOP = 0, ORI__SOLID_BOTTOM = 1, ORI__SOLID_RIM = 2 } ori__solid_part;
typedef struct ori__solid {
    int point_count, tri_count;
    ori_v3 *points;
    int *point_vertex;  // FOLD vertex a point was offset from
    int (*tris)[3];
    unsigned char *part; // ori__solid_part per triangle
    int *tri_face;       // FOLD face of a top/bottom triangle; the face beside a rim triangle
    int *tri_panel;      // panel (closed solid) of every triangle, 0 … panel_count − 1
    int panel_count;     // closed panel solids
    int stacked_panels;  // panels lifted by their layer onto another panel of their plane
    int front_panels;    // panels put on the front side of the sheet (their back would overlap)
    int overlapping_pairs; // triangle prisms of different panels still overlapping (0 when solved)
} ori__solid;
void ori__solid_build(const ori_mesh *m, double thickness, const int *face_orders, int face_order_count,
                      ori__solid *out);
void ori__solid_free(ori__solid *s);

// --- depth order (order.c) -----------------------------------------------------------------

// A polygon to fill, in image coordinates (x right, y down, z depth), with per-side edge tags.
typedef struct ori__piece {
    int face;        // FOLD face
    int first, count; // its points in the order's point array
} ori__piece;
typedef struct ori__order {
    int piece_count, point_count;
    ori__piece *pieces;  // back to front
    ori_v3 *points;      // image coordinates
    int *side_edge;      // per point: FOLD edge of the side from this point to the next, or -1
    int groups_split;    // groups of faces that needed splitting (cycles or intersections)
    int fragments;       // pieces produced by splitting
} ori__order;
// Sort the faces of a posed mesh back to front for camera: overlapping faces in the image
// are compared where they overlap; cycles and intersecting faces are split by a BSP of their
// triangles; faces folded flat onto each other are ordered by face_orders (FOLD faceOrders,
// face_order_count triples (f, g, s); may be NULL) where a pair is listed, else stacked along
// the fold tree. face_orders must have passed ori__face_orders_check.
void ori__order_build(const ori_mesh *m, const ori_camera *camera, const int *face_orders, int face_order_count,
                      ori__order *out);
// Check FOLD faceOrders against a mesh: faces in range and distinct, s = ±1 (ORI_ERR_ARGUMENT
// naming the triple, field "faceOrders").
ori_status ori__face_orders_check(const ori_mesh *m, const int *face_orders, int face_order_count, ori_error *error);
void ori__order_free(ori__order *o);

// --- drawing (draw.c) ----------------------------------------------------------------------

// Draw a state onto a Cairo context of def's size. scene_lo/hi (may be NULL) fix the box the
// ground grid is drawn from (an animation's union of every frame). texture may be NULL.
ori_status ori__draw(cairo_t *cr, const ori_mesh *mesh, const ori_pattern *pattern, const ori_render_def *def,
                     const ori_camera *camera, cairo_surface_t *texture, const ori_v3 *scene_lo,
                     const ori_v3 *scene_hi, ori_error *error);
// Decode a PNG texture (ORI_ERR_PARSE when it is not one). *out is NULL when def has none.
ori_status ori__texture_load(const ori_render_def *def, cairo_surface_t **out, ori_error *error);
// Check def's size (ORI_ERR_ARGUMENT naming the limit).
ori_status ori__render_check_size(const ori_render_def *def, ori_error *error);
// The camera of def fitted to points (when def->fit_camera).
ori_camera ori__render_fit(const ori_render_def *def, const ori_v3 *points, int count);
// Points a 3D drawing must show: the mesh's vertices and, with a grid, the grid's corners
// (from scene_lo/hi when given). Returns the count written into out (capacity vertex_count + 4).
int ori__render_scene_points(const ori_mesh *m, const ori_render_def *def, const ori_v3 *scene_lo,
                             const ori_v3 *scene_hi, ori_v3 *out);

// The layer offset of every face (face_count entries) from the fold tree: faces folded flat onto
// each other step by their normal, by the sign of the crease between them (order.c).
void ori__render_stacking(const ori_mesh *m, ori_v3 *layer);

// --- colour by value (colormap.c) ---------------------------------------------------------

// Whether a value map paints anything (face or edge values given).
bool ori__value_map_active(const ori_value_map *map);
// Check an active map's range (ORI_ERR_ARGUMENT, field "values"); ORI_OK for an inactive one.
ori_status ori__value_map_check(const ori_value_map *map, ori_error *error);

#endif
