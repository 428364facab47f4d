// Shared by the mesh writers (mesh_write.c: OBJ, STL, PLY and the dispatch; mesh_write_gltf.c:
// glTF and GLB): the exported surface (mesh_surface.c) as parts of triangles with their own
// vertices. mesh_write.c calls mesh_write_gltf.c and mesh_surface.c; gltf calls only the surface.
#ifndef ORI_MESH_WRITE_INTERNAL_H
#define ORI_MESH_WRITE_INTERNAL_H

#include "../io/io_internal.h"
#include "render_internal.h"

// The parts of an exported surface, each drawn with its own material.
enum { ORI__PART_FRONT = 0, ORI__PART_BACK = 1, ORI__PART_RIM = 2, ORI__PART_COUNT = 3 };

// A part: vertices (position in world coordinates, unit normal, flat-sheet texture coordinate,
// the FOLD vertex it came from) and triangles (counter-clockwise seen from outside) with their
// FOLD face.
typedef struct ori__xpart {
    int vcount, tcount;
    ori_v3 *pos, *nrm;
    ori_v2 *uv;
    int *fold_vertex;
    int (*tri)[3];
    int *fold_face;
    int *panel; // thick solid: the panel (closed solid) of every triangle; NULL for the sheet
} ori__xpart;

typedef struct ori__xmesh {
    ori__xpart part[ORI__PART_COUNT];
    bool has_uv;
    int panel_count, stacked_panels; // thick solid: closed panels, and those offset by their layer
} ori__xmesh;

// Texture coordinates: the flat sheet's bounding box stretched over [0, 1]², v downwards.
typedef struct ori__uv_map {
    double x0, y0, dx, dy;
} ori__uv_map;
ori__uv_map ori__uv_of_mesh(const ori_mesh *m);
// The texture coordinate of a reference point (glTF's v downwards).
static inline ori_v2 ori__uv_at(const ori__uv_map *u, ori_v3 ref)
{
    return ori_v2_make((ref.x - u->x0) / u->dx, 1.0 - (ref.y - u->y0) / u->dy);
}

// The surface of a mesh in its current pose: the two-sided sheet (thickness 0) or the closed
// solid. With reference = true, the sheet in its reference position (animated glTF nodes).
// def gives the thickness and the faceOrders of the thick panels.
void ori__xmesh_build(const ori_mesh *m, const ori_export_def *def, bool reference, ori__xmesh *out);
// The sheet of one face (front and back parts) in its reference position.
void ori__xmesh_face(const ori_mesh *m, int face, const ori__uv_map *uv, ori__xmesh *out);
void ori__xmesh_free(ori__xmesh *x);

// glTF 2.0 (embedded buffer) or GLB into out.
void ori__gltf_write(const ori_mesh *m, const ori_export_def *def, bool binary, ori__text *out);

#endif
