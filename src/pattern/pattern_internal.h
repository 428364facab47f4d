// The crease pattern's storage, shared by library modules (io, flat, kinematics, axioms...).
// cli/ never includes this: it uses <orikin/pattern.h>.
#ifndef ORI_PATTERN_INTERNAL_H
#define ORI_PATTERN_INTERNAL_H

#include <orikin/pattern.h>

#include "../core/core_internal.h"

struct ori_pattern {
    // Primary data (FOLD fields).
    int vertex_count, vertex_cap;
    ori_v3 *vertices;
    int edge_count, edge_cap;
    ori_edge *edges;
    int face_count, face_cap;       // faces
    int *face_offsets;              // face_count + 1 entries (face_offsets[0] = 0)
    int face_vertex_count, face_vertex_cap;
    int *face_vertices;             // concatenated cycles
    char (*face_names)[ORI_NAME_MAX]; // face_cap entries or NULL; "" = unnamed
    int tree_count, tree_cap;
    ori_tree_node *tree;
    int *tree_hash;                 // open addressing over tree names: node index or -1 (the first of equal names)
    int tree_hash_cap;              // a power of two > 2 × tree_count, or 0
    bool folded_form;
    bool has_fold_angles;
    int absent_fold_angles;         // edges whose file fold angle was null (read as 0)
    int planarized_from;            // FOLD frame planarised on reading: the file's edge count (0: not planarised)

    // Derived topology, valid while built is true.
    bool built;
    int *vert_edge_offsets; // vertex_count + 1
    int *vert_edges;        // 2 × edge_count, cyclic CCW order per vertex
    int *face_edges;        // parallel to face_vertices
    int *edge_faces;        // 2 × edge_count: left, right of v[0]→v[1]
    int *edge_hash;         // open addressing: edge index or -1; capacity edge_hash_cap
    int edge_hash_cap;
    double diagonal;
};

// Grow face storage (offsets, names, vertex cycles) to hold the given totals.
void ori__pattern_reserve_faces(ori_pattern *p, int faces, int face_vertices);
// Rebuild the index of the tree's names after the tree was changed in place (a node deleted).
void ori__pattern_reindex_tree(ori_pattern *p);
// Drop derived topology (called by every topology mutation).
void ori__pattern_invalidate(ori_pattern *p);
// Twice the signed area of a face in the xy-plane (> 0: counter-clockwise).
double ori__pattern_face_area2(const ori_pattern *p, int face);
// Connected parts of the pattern's graph (edges joining vertices; an isolated vertex is a part of
// its own): part[v] = the smallest vertex index of v's part, for the vertex_count entries of
// part. Returns the number of parts.
int ori__pattern_parts(const ori_pattern *p, int *part);
// 2D position of a vertex (x, y).
static inline ori_v2 ori__pattern_v2(const ori_pattern *p, int v)
{
    return ori_v2_make(p->vertices[v].x, p->vertices[v].y);
}

#endif
