/// orikin render: pictures, animations and meshes of any state (SPEC capability 9, thesis ch.
/// 9.6). A state view (a built pattern with the world position of every vertex) becomes a posed
/// mesh: every face triangulated once, in the flat sheet, by ear clipping with exact orientation
/// tests, with its front side (the side facing +z in the flat sheet) known. A camera projects it;
/// drawings go to SVG, PDF (true vector: faces sorted back to front, cycles split) or PNG through
/// Cairo, animations to GIF through giflib, meshes to OBJ, STL, PLY, glTF 2.0 and GLB.
/// docs/render.md has the algorithms and the file layouts.
///
/// Functions: ori_rgb_parse, ori_mesh_create, ori_mesh_destroy, ori_mesh_set_pose,
/// ori_mesh_vertex_count, ori_mesh_face_count, ori_mesh_triangle_count, ori_mesh_triangle_at,
/// ori_mesh_face_triangles, ori_mesh_vertex, ori_mesh_reference_vertex, ori_mesh_has_flat,
/// ori_mesh_face_normal, ori_mesh_area, ori_mesh_bounds, ori_mesh_face_pose, ori_camera_preset,
/// ori_camera_fit, ori_camera_project, ori_image_format_from_path, ori_image_format_name,
/// ori_default_render_def, ori_render_camera, ori_render_image, ori_render_file,
/// ori_default_gif_def, ori_gif_write, ori_mesh_format_from_path, ori_mesh_format_name,
/// ori_default_export_def, ori_mesh_export, ori_mesh_export_mtl, ori_mesh_export_file,
/// ori_mesh_thick_panels, ori_colormap, ori_value_map_position, ori_value_map_ticks.
///
/// Frames. World coordinates are the pattern's (the flat sheet in z = 0, +z its front side).
/// Images have x to the right and y downwards, in pixels (PNG, GIF) or points (SVG, PDF).
#ifndef ORIKIN_RENDER_H
#define ORIKIN_RENDER_H

#include "base.h"
#include "formats.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Largest image width or height accepted (pixels or points).
#define ORI_RENDER_MAX_SIZE 16384

/// A colour, each component in [0, 1].
typedef struct ori_rgb {
    double r, g, b;
} ori_rgb;

/// Parse a colour: "#rrggbb", "#rgb" or a name (white, black, grey/gray, silver, red, green,
/// blue, yellow, orange, purple, pink, brown, cyan, magenta, navy, teal, olive, maroon, gold,
/// ivory, beige, tan, salmon, coral, skyblue, lightblue). False for anything else.
ORI_API bool ori_rgb_parse(const char *text, ori_rgb *out);

// --- the state and its mesh -------------------------------------------------------------

/// A state to draw or export (nothing is copied; the pointers must stay valid while used).
typedef struct ori_state_view {
    const ori_pattern *pattern;    ///< built pattern with faces: a flat crease pattern (whose coordinates are the flat sheet) or a folded form
    const ori_v3 *positions;       ///< world position of every vertex (vertex_count), or NULL for the pattern's own coordinates
    const double *fold_angles_rad; ///< fold angle of every edge (edge_count, radians), or NULL for the pattern's (then the assignment gives the sign); decides which of two faces folded flat onto each other lies on top
} ori_state_view;

/// Opaque posed mesh: the faces of a state triangulated, with normals and flat-sheet coordinates.
typedef struct ori_mesh ori_mesh;

/// A triangle of the mesh: three FOLD vertices counter-clockwise seen from the front side of
/// its face, and that face.
typedef struct ori_mesh_triangle {
    int v[3];
    int face;
} ori_mesh_triangle;

/// Triangulate a state's faces (ear clipping with exact orientation tests, in the flat sheet,
/// or for a folded form in the plane of each face) and pose them. Fails with ORI_ERR_ARGUMENT
/// for an unbuilt pattern or one without faces, ORI_ERR_RANGE (field vertices_coords) for a
/// position that is not finite. Destroy with ori_mesh_destroy.
ORI_API ori_status ori_mesh_create(const ori_state_view *state, ori_mesh **out, ori_error *error);
/// Destroy a mesh; NULL is a no-op.
ORI_API void ori_mesh_destroy(ori_mesh *mesh);
/// Pose the same mesh in another state of its pattern (an animation frame): positions
/// (vertex_count) and optional fold angles (edge_count, radians) as in ori_state_view. The
/// triangulation is kept. Fails with ORI_ERR_RANGE for a position that is not finite.
ORI_API ori_status ori_mesh_set_pose(ori_mesh *mesh, const ori_v3 *positions, const double *fold_angles_rad,
                                     ori_error *error);

/// Number of vertices, faces and triangles (vertices and faces are those of the pattern).
ORI_API int ori_mesh_vertex_count(const ori_mesh *mesh);
ORI_API int ori_mesh_face_count(const ori_mesh *mesh);
ORI_API int ori_mesh_triangle_count(const ori_mesh *mesh);
/// A triangle by value; triangles are grouped by face, faces in FOLD order.
ORI_API ori_mesh_triangle ori_mesh_triangle_at(const ori_mesh *mesh, int triangle);
/// The first triangle of a face and their number (n − 2 for a simple face of n vertices).
ORI_API int ori_mesh_face_triangles(const ori_mesh *mesh, int face, int *first);
/// World position of a vertex in the current pose.
ORI_API ori_v3 ori_mesh_vertex(const ori_mesh *mesh, int vertex);
/// Reference position of a vertex: in the flat sheet (z = 0) when the mesh has one, else its
/// position when the mesh was created. Texture coordinates and animated meshes use it.
ORI_API ori_v3 ori_mesh_reference_vertex(const ori_mesh *mesh, int vertex);
/// True when the pattern is a flat crease pattern (its coordinates are the flat sheet).
ORI_API bool ori_mesh_has_flat(const ori_mesh *mesh);
/// Unit normal of a face's front side in the current pose (zero for a degenerate face).
ORI_API ori_v3 ori_mesh_face_normal(const ori_mesh *mesh, int face);
/// Total area of the triangles in the current pose (pattern units squared).
ORI_API double ori_mesh_area(const ori_mesh *mesh);
/// Axis-aligned bounding box of the current pose.
ORI_API void ori_mesh_bounds(const ori_mesh *mesh, ori_v3 *lo, ori_v3 *hi);
/// The rigid motion of a face from its reference position to positions (vertex_count world
/// coordinates), built from the face's normal and longest side. Fails with ORI_ERR_DEGENERATE
/// (field faces_vertices, element = face) when positions miss that motion by more than
/// ORI_TOL_POSE_FIT_REL × the reference diagonal (the face is bent or stretched).
ORI_API ori_status ori_mesh_face_pose(const ori_mesh *mesh, int face, const ori_v3 *positions, ori_rigid *out,
                                      ori_error *error);

// --- camera -------------------------------------------------------------------------------

/// Preset view directions. The image's up is world +z except for top and bottom (+y and −y).
typedef enum ori_camera_preset_kind {
    ORI_CAMERA_ISO = 0, ///< from the front-right, above: eye direction (1, −1, 1)
    ORI_CAMERA_TOP,     ///< looking down −z: x right, y up
    ORI_CAMERA_FRONT,   ///< looking along +y: x right, z up
    ORI_CAMERA_SIDE,    ///< looking along −x: y right, z up
    ORI_CAMERA_BOTTOM,  ///< looking up +z: x right, y down
} ori_camera_preset_kind;

/// A camera. View coordinates: x right, y up, z towards the viewer.
typedef struct ori_camera {
    ori_m3 rotation;  ///< world → view rotation (rows: the image's right, up and towards-the-viewer axes in world coordinates)
    ori_v3 target;    ///< world point drawn at (cx, cy)
    double cx, cy;    ///< image position of the target (x right, y down)
    double scale;     ///< image units per world unit (at the target's depth with perspective)
    bool perspective; ///< perspective from an eye at distance from the target; otherwise orthographic
    double distance;  ///< eye–target distance in world units (perspective)
} ori_camera;

/// Eye distance of a fitted perspective camera, in radii of the points' bounding sphere (a
/// field of view of about 2·asin(1/3) ≈ 39°).
#define ORI_CAMERA_PERSPECTIVE_DISTANCE 3.0

/// A preset turned by yaw (about world z, before the preset: the model turns counter-clockwise
/// seen from above), then pitch (about the image's right axis: the top comes towards the
/// viewer) and roll (about the view axis: counter-clockwise on the image). Radians. Target at
/// the origin, scale 1, orthographic.
ORI_API ori_camera ori_camera_preset(ori_camera_preset_kind preset, double yaw_rad, double pitch_rad,
                                     double roll_rad);
/// Centre and scale the camera (keeping its rotation and projection) so that every point lies
/// inside a width × height image with a margin of margin_rel × the smaller side; a perspective
/// camera also gets its distance (ORI_CAMERA_PERSPECTIVE_DISTANCE). count ≥ 1.
ORI_API void ori_camera_fit(ori_camera *camera, const ori_v3 *points, int count, int width, int height,
                            double margin_rel);
/// Image coordinates of a world point: x, y (right, down) and z = its depth in world units,
/// distance from the eye along the view axis (perspective) or minus the view z (orthographic),
/// larger = farther. With perspective, a point at or behind the eye has z ≤ 0 and is not drawn.
ORI_API ori_v3 ori_camera_project(const ori_camera *camera, ori_v3 p_world);

// --- images -------------------------------------------------------------------------------

/// Image file formats: ori_image_format (formats.h, the table of every file format).
/// The format of a path by its extension (.svg, .pdf, .png; any case), else ORI_IMAGE_UNKNOWN.
ORI_API ori_image_format ori_image_format_from_path(const char *path);
/// Lower-case name of a format ("png"); static string.
ORI_API const char *ori_image_format_name(ori_image_format format);

/// Light of the 3D view: a side whose normal n (view coordinates: x right, y up, z towards the
/// viewer) faces the viewer gets its colour × (AMBIENT + DIFFUSE · max(0, n·l)), l the unit
/// vector along (LIGHT_X, LIGHT_Y, LIGHT_Z): light from the upper left, in front.
#define ORI_RENDER_AMBIENT 0.55
#define ORI_RENDER_DIFFUSE 0.45
#define ORI_RENDER_LIGHT_X -1.0
#define ORI_RENDER_LIGHT_Y 1.5
#define ORI_RENDER_LIGHT_Z 2.5
/// Width (image units) of the outline drawn in a face's own colour around it, which covers the
/// antialiasing seams between adjacent faces.
#define ORI_RENDER_SEAM_WIDTH 0.5

// --- colour by value ------------------------------------------------------------------------

/// Values shown in colour (docs/render.md, "Colour by value"): faces and/or edges painted with
/// ori_colormap over [min, max]. A picture gets a colour bar on its right (min at the bottom, max
/// at the top, labelled ticks from ori_value_map_ticks), the drawing fitted to the rest; a glTF
/// gets the faces' colours as COLOR_0. A NaN value keeps the usual colour of its face or edge.
typedef struct ori_value_map {
    const double *face_values; ///< per face (face_count), or NULL; borrowed. Faces so painted are not shaded or textured
    const double *edge_values; ///< per edge (edge_count), or NULL; borrowed. Drawn edges with a value are stroked solid in its colour (images only)
    double min, max;           ///< the bar's range: finite, min ≤ max; values outside are clamped to it
} ori_value_map;

/// Most ticks on a colour bar, and the longest tick label (with its terminating zero).
#define ORI_RENDER_BAR_TICKS 5
#define ORI_RENDER_BAR_LABEL_MAX 16

/// The colour map: a perceptually uniform blue–green–yellow ramp (matplotlib's viridis, as a
/// degree-8 polynomial per channel fitted by least squares, within 2.4/255 of it; the fit is
/// scripts/fit_viridis.py). t is clamped to [0, 1] (NaN gives t = 0). sRGB components.
ORI_API ori_rgb ori_colormap(double t);
/// Where a value lies on the bar: (value − min) / (max − min) clamped to [0, 1]; 0 when
/// min = max or value is NaN.
ORI_API double ori_value_map_position(const ori_value_map *map, double value);
/// The colour bar's ticks: values[k] (bottom to top, the first min, the last max) and their
/// labels ("%.3g"; a tick within ORI_TOL_BAR_ZERO_REL of the range's size from zero reads "0").
/// Returns ORI_RENDER_BAR_TICKS, or 1 when min = max. values or labels may be NULL.
ORI_API int ori_value_map_ticks(const ori_value_map *map, double *values, char (*labels)[ORI_RENDER_BAR_LABEL_MAX]);

/// What to draw.
typedef enum ori_render_view {
    ORI_RENDER_CREASES = 0, ///< the flat crease pattern, thesis line styles
    ORI_RENDER_3D,          ///< the posed sheet
} ori_render_view;

/// Drawing parameters; get them from ori_default_render_def().
typedef struct ori_render_def {
    ori_render_view view;
    ori_image_format format;
    int width, height;        ///< image size in pixels (PNG) or points (SVG, PDF), 1 … ORI_RENDER_MAX_SIZE
    ori_camera camera;        ///< 3D view: orientation and projection
    bool fit_camera;          ///< fit the camera's target and scale to the state (ori_camera_fit, margin 5 %)
    ori_rgb front, back;      ///< 3D view: colours of the two sides
    ori_rgb background;       ///< background (also the PNG's, which is opaque)
    bool shading;             ///< 3D view: directional light (docs/render.md); false = flat colours
    bool all_edges;           ///< 3D view: also draw F creases and J edges (default: M, V, U, cuts and the boundary)
    bool grid;                ///< 3D view: a ground grid under the sheet (z = its lowest point)
    bool labels;              ///< crease view: vertex, edge and face indices
    bool mark_failing;        ///< crease view: ring the interior vertices that are not locally flat-foldable (ori_flat_check_pattern)
    const void *texture_png;  ///< 3D view: PNG image (bytes) mapped on the front side by flat-sheet coordinates, or NULL
    size_t texture_size;      ///< its size in bytes
    const int *face_orders;   ///< 3D view: the state's FOLD faceOrders, face_order_count triples (f, g, s): f lies on the side of g's normal (s = +1) or the other (s = −1); they order faces folded flat onto each other where a pair is listed (else stacking along the fold tree, docs/render.md); borrowed; NULL: none
    int face_order_count;     ///< number of triples in face_orders
    ori_value_map values;     ///< colour by value (both views) with a colour bar; default none (NULL arrays)
    double line_width_rel;    ///< line width as a fraction of the smaller image side, at least 0.75 image units but at most 1/12 of the mean edge length in the image (dense patterns)
    int internal_value;       ///< set by ori_default_render_def; do not change
} ori_render_def;

/// Defaults: crease view, PNG, 800 × 600, iso camera fitted, amber front (#e8a33d) and ivory
/// back (#f3efe4) on white, shading on, no grid, labels off, failing vertices marked, no
/// texture, no faceOrders, no values (colour by value off), line width 1/400 of the smaller side.
ORI_API ori_render_def ori_default_render_def(void);

/// The camera a 3D drawing of the state uses (def's camera, fitted when def->fit_camera).
/// Fails as ori_mesh_create.
ORI_API ori_status ori_render_camera(const ori_state_view *state, const ori_render_def *def, ori_camera *out,
                                     ori_error *error);
/// Draw a state into memory (*data, *size: the whole file; free with ori_buffer_free). Fails
/// with ORI_ERR_ARGUMENT for a size out of range, an unknown format or faceOrders naming a face
/// that does not exist (or with s not ±1), ORI_ERR_UNSUPPORTED for
/// the crease view of a folded form, ORI_ERR_PARSE for a texture that is not a readable PNG,
/// ORI_ERR_ARGUMENT for values whose range is not finite with min ≤ max, and as ori_mesh_create.
ORI_API ori_status ori_render_image(const ori_state_view *state, const ori_render_def *def, void **data,
                                    size_t *size, ori_error *error);
/// Draw a state to path atomically (ori_file_write_atomic) in the format of the path's
/// extension (def->format when the extension is none of .svg, .pdf, .png).
ORI_API ori_status ori_render_file(const ori_state_view *state, const ori_render_def *def, const char *path,
                                   ori_error *error);

// --- animations ---------------------------------------------------------------------------

/// Supplies frame index (0 … frame_count − 1) of an animation into *out (valid until the next
/// call; the pattern must be the same in every frame). Returning a failure stops the animation.
typedef ori_status ori_frame_fn(int index, ori_state_view *out, void *user, ori_error *error);

/// Supplies frame index's values for an animation coloured by value: *face_values (face_count)
/// or *edge_values (edge_count), the other NULL (valid until the next call). NaN keeps a face's
/// or edge's usual colour.
typedef ori_status ori_frame_values_fn(int index, const double **face_values, const double **edge_values, void *user,
                                       ori_error *error);

/// Animation parameters; get them from ori_default_gif_def().
typedef struct ori_gif_def {
    ori_render_def render;    ///< how a frame is drawn (format ignored; render.values' arrays must be NULL: with frame_values its min and max are the bar's range for every frame); with fit_camera the camera is fitted once to every frame, so the shape does not jump
    ori_frame_values_fn *frame_values; ///< colour by value, frame by frame, under one colour bar (render.values.min … max); NULL: none
    int frame_count;          ///< ≥ 1
    ori_frame_fn *frame;      ///< the frames (each is asked for more than once)
    void *user;               ///< passed to frame
    double fps;               ///< frames per second, 1 … 100 (the delay is rounded to 1/100 s)
    double hold_last_s;       ///< extra seconds the last frame stays before the loop restarts (≥ 0)
    bool loop;                ///< loop forever
    ori_progress_fn *progress; ///< called with the fraction drawn (may be NULL); returning false cancels
    void *progress_user;
    int internal_value;       ///< set by ori_default_gif_def; do not change
} ori_gif_def;

/// Defaults: 3D view render def, no frames (set them), 15 fps, the last frame held 1 s, looping.
ORI_API ori_gif_def ori_default_gif_def(void);
/// Draw every frame and encode an animated GIF into memory (free *data with ori_buffer_free).
/// One global palette of 256 colours by median cut over sample frames (docs/render.md), each
/// frame stored as the rectangle that changed. Fails as ori_render_image, with ORI_ERR_LIMIT
/// when cancelled, and with ORI_ERR_ARGUMENT for render values given as arrays (an animation
/// takes them frame by frame from frame_values) or a frame giving none or both.
ORI_API ori_status ori_gif_write(const ori_gif_def *def, void **data, size_t *size, ori_error *error);

// --- meshes -------------------------------------------------------------------------------

/// Mesh file formats: ori_mesh_format (formats.h, the table of every file format).
/// The format of a path by its extension (.obj, .stl, .ply, .gltf, .glb; any case).
ORI_API ori_mesh_format ori_mesh_format_from_path(const char *path);
/// Lower-case name of a format ("gltf"); static string.
ORI_API const char *ori_mesh_format_name(ori_mesh_format format);

/// Export parameters; get them from ori_default_export_def().
typedef struct ori_export_def {
    ori_mesh_format format;
    double thickness;                ///< 0: a two-sided sheet; > 0: separate closed offset panel solids thickness thick (pattern units; docs/render.md)
    ori_rgb front, back, edge;       ///< materials: front side, back side, the solid's rims
    int keyframe_count;              ///< glTF/GLB: 0 = the current pose; ≥ 1 = an animation, one node per face (or one morphing mesh: keyframe_positions)
    const double *keyframe_times_s;  ///< keyframe_count increasing times (seconds)
    const ori_rigid *keyframe_poses; ///< keyframe_count × face_count poses (keyframe-major) mapping reference positions (ori_mesh_reference_vertex) to world positions
    const ori_v3 *keyframe_positions; ///< instead of keyframe_poses (NULL): keyframe_count × vertex_count world positions (keyframe-major), for faces that bend
                                      ///< (a compliant fold): one mesh, posed as keyframe 0 (the mesh's own pose must be it), morphing to each keyframe (a morph target each after the first)
    const char *obj_mtllib;          ///< OBJ: the material library file its "mtllib" line names (NULL: none; ori_mesh_export_file sets it)
    const int *face_orders;          ///< thick panels: the state's FOLD faceOrders (face_order_count triples f, g, s as in ori_render_def) ranking panels stacked flat; borrowed; NULL: stacking along the fold tree
    int face_order_count;            ///< number of triples in face_orders
    ori_value_map values;            ///< glTF/GLB: values.face_values become every vertex's COLOR_0 (linear RGB of ori_colormap; a face's vertices are its own); NULL: none. Other formats ignore it
    int internal_value;              ///< set by ori_default_export_def; do not change
} ori_export_def;

/// The tag a thick export carries (OBJ comment, STL solid names, PLY comment), followed by the
/// thickness: the file holds separate closed panel solids, not one connected surface.
#define ORI_THICK_PANEL_TAG "orikin thick panels, thickness"

/// What a thick export makes of a posed mesh (ori_mesh_thick_panels).
typedef struct ori_thick_info {
    int panels;      ///< closed panel solids (flat regions of the sheet)
    int stacked;     ///< panels lifted by their layer onto (a slab above) another panel of their plane that they overlap
    int front;       ///< panels put on the front side of the sheet because their back side would overlap another panel
    int overlapping; ///< pairs of panel triangles (as prisms) whose interiors still overlap; 0 when every panel is clear
} ori_thick_info;

/// What the thick export of the mesh in its current pose makes with def (thickness > 0, its
/// faceOrders). Fails as ori_mesh_export, and with ORI_ERR_ARGUMENT for a thickness of 0.
ORI_API ori_status ori_mesh_thick_panels(const ori_mesh *mesh, const ori_export_def *def, ori_thick_info *out,
                                         ori_error *error);

/// Defaults: glTF, no thickness, the render colours (front, back) and grey rims, no animation,
/// no values (no vertex colours).
ORI_API ori_export_def ori_default_export_def(void);
/// Write the mesh in its current pose (or animated) into memory (*data, *size; free with
/// ori_buffer_free). Fails with ORI_ERR_ARGUMENT for an unknown format, a negative or
/// non-finite thickness, keyframes for a format other than glTF/GLB or with a thickness,
/// times that do not increase, or face values whose range is not finite with min ≤ max.
ORI_API ori_status ori_mesh_export(const ori_mesh *mesh, const ori_export_def *def, void **data, size_t *size,
                                   ori_error *error);
/// The OBJ material library (MTL text: materials front, back and rim with def's colours) into
/// memory (free *data with ori_buffer_free).
ORI_API ori_status ori_mesh_export_mtl(const ori_export_def *def, void **data, size_t *size, ori_error *error);
/// Write the mesh to path atomically in the format of the path's extension (def->format when
/// the extension is none of .obj, .stl, .ply, .gltf, .glb). An OBJ comes with its material
/// library beside it: path with .mtl for .obj (written first; removed if the OBJ fails).
ORI_API ori_status ori_mesh_export_file(const ori_mesh *mesh, const ori_export_def *def, const char *path,
                                        ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
