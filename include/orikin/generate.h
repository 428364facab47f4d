/// orikin generate: standard tessellation crease patterns built directly (index arithmetic, no
/// crease insertion): Miura-ori, Yoshimura, waterbomb, square twist and Kresling, with a valid
/// mountain/valley assignment, explicit flat fold angles (0), counter-clockwise faces and a
/// class per edge (which family of creases it belongs to). docs/generators.md has the geometry.
///
/// Functions: ori_tessellation_params, ori_tessellation_name, ori_tessellation_from_name, ori_edge_class_name,
/// ori_default_generate_def, ori_generate_counts, ori_generate, ori_kresling_bistable_height.
///
/// Lengths are unitless; angles are radians. Sizes up to ORI_GENERATE_MAX_EDGES edges.
#ifndef ORIKIN_GENERATE_H
#define ORIKIN_GENERATE_H

#include "base.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Largest number of edges a generator produces; larger requests fail with ORI_ERR_LIMIT.
#define ORI_GENERATE_MAX_EDGES ((int64_t)1 << 26)

/// The tessellations orikin generates.
typedef enum ori_tessellation {
    ORI_TESS_MIURA = 0,   ///< "miura": parallelogram cells, straight and zig-zag creases
    ORI_TESS_YOSHIMURA,   ///< "yoshimura": diamond (triangle) pattern, degree-6 vertices
    ORI_TESS_WATERBOMB,   ///< "waterbomb": offset rows of waterbomb bases, degree-6 vertices
    ORI_TESS_SQUARE_TWIST,///< "square-twist": grid of square twists of alternating handedness
    ORI_TESS_KRESLING,    ///< "kresling": triangulated cylinder, developed as a flat strip
    ORI_TESS_COUNT
} ori_tessellation;

/// The ori_generate_def fields a tessellation reads (ori_tessellation_params gives them as bits).
typedef enum ori_generate_param {
    ORI_GEN_ROWS = 1 << 0,            ///< rows
    ORI_GEN_COLS = 1 << 1,            ///< cols
    ORI_GEN_SIDES = 1 << 2,           ///< sides
    ORI_GEN_ANGLE = 1 << 3,           ///< angle_rad
    ORI_GEN_WIDTH = 1 << 4,           ///< width
    ORI_GEN_HEIGHT = 1 << 5,          ///< height
    ORI_GEN_TWIST_SIZE = 1 << 6,      ///< twist_size
    ORI_GEN_BISTABLE_HEIGHT = 1 << 7, ///< bistable_height (on by default where read)
} ori_generate_param;

/// The parameters a tessellation reads: a set of ori_generate_param bits (one row of the
/// generators' table, which also holds its defaults, counts and writer).
ORI_API unsigned ori_tessellation_params(ori_tessellation kind);
/// Command-line name of a tessellation ("square-twist"); static string.
ORI_API const char *ori_tessellation_name(ori_tessellation kind);
/// Parse a tessellation name (as ori_tessellation_name gives). Returns false when unknown.
ORI_API bool ori_tessellation_from_name(const char *name, ori_tessellation *out);

/// The family a generated edge belongs to (written to FOLD as "orikin:edges_class").
typedef enum ori_edge_class {
    ORI_EDGE_CLASS_BOUNDARY = 0, ///< "boundary": sheet boundary (assignment B)
    ORI_EDGE_CLASS_STRAIGHT,     ///< "straight": Miura creases along the straight lines (x direction)
    ORI_EDGE_CLASS_ZIGZAG,       ///< "zigzag": Miura creases along the zig-zag lines
    ORI_EDGE_CLASS_HORIZONTAL,   ///< "horizontal": Yoshimura / waterbomb creases along x
    ORI_EDGE_CLASS_VERTICAL,     ///< "vertical": waterbomb creases along y
    ORI_EDGE_CLASS_DIAGONAL,     ///< "diagonal": Yoshimura / waterbomb diagonals, Kresling valley diagonals
    ORI_EDGE_CLASS_SQUARE,       ///< "square": sides of a square twist's central square
    ORI_EDGE_CLASS_PLEAT,        ///< "pleat": square twist pleat lines
    ORI_EDGE_CLASS_POLYGON,      ///< "polygon": Kresling polygon edges between storeys
    ORI_EDGE_CLASS_LATERAL,      ///< "lateral": Kresling lateral (mountain) creases
    ORI_EDGE_CLASS_SEAM,         ///< "seam": Kresling seam, a boundary of the flat strip (B)
    ORI_EDGE_CLASS_COUNT
} ori_edge_class;

/// Name of an edge class ("zigzag"); static string.
ORI_API const char *ori_edge_class_name(ori_edge_class c);

/// Generator parameters; get them from ori_default_generate_def(kind). Which fields a
/// tessellation reads, their meaning and ranges are listed in docs/generators.md.
typedef struct ori_generate_def {
    ori_tessellation kind; ///< which tessellation
    int rows;              ///< rows of cells / bases / twists, storeys of the Kresling (≥ 1)
    int cols;              ///< columns of cells / bases / twists (≥ 1; not read by Kresling)
    int sides;             ///< Kresling: sides n of the polygon (≥ 3)
    double angle_rad;      ///< Miura γ, Yoshimura θ, square twist α, Kresling twist φ (radians)
    double width;          ///< length along x: Miura a, Yoshimura/waterbomb base width, tile width, polygon side (> 0)
    double height;         ///< Miura b, waterbomb base height, tile height, Kresling storey height (> 0)
    double twist_size;     ///< square twist: central square size as a fraction of the largest that fits (0, 1)
    bool bistable_height;  ///< Kresling: ignore height and use the height at which a storey also folds flat
    int internal_value;    ///< set by ori_default_generate_def; do not change
} ori_generate_def;

/// Defaults for a tessellation: 4 × 4 cells, unit sizes, and Miura γ = 60°, Yoshimura θ = 30°,
/// square twist α = 45° with twist_size 0.5, Kresling n = 6, 3 storeys, φ = 30°, bistable height.
ORI_API ori_generate_def ori_default_generate_def(ori_tessellation kind);

/// Vertex, edge and face counts of a generated pattern.
typedef struct ori_pattern_counts {
    int64_t vertices; ///< vertices_coords entries
    int64_t edges;    ///< edges_vertices entries
    int64_t faces;    ///< faces_vertices entries
} ori_pattern_counts;

/// Check the parameters and give the counts the generator will produce (closed formulas,
/// docs/generators.md). Fails with ORI_ERR_ARGUMENT (field = the parameter, message with the
/// allowed range) or ORI_ERR_LIMIT (more than ORI_GENERATE_MAX_EDGES edges).
ORI_API ori_status ori_generate_counts(const ori_generate_def *def, ori_pattern_counts *out, ori_error *error);

/// Generate the pattern (built: validated, topology ready) with every fold angle 0 (flat) and
/// explicit fold angles. classes (may be NULL) receives one ori_edge_class per edge, freed with
/// ori_buffer_free. *out is NULL on failure; destroy with ori_pattern_destroy.
ORI_API ori_status ori_generate(const ori_generate_def *def, ori_pattern **out, ori_edge_class **classes,
                                ori_error *error);

/// Kresling storey height at which a storey of an n-gon with side a and twist angle_rad also
/// folds flat with rigid triangles (Guest & Pellegrino 1994): h² = 4R²·cos(π/n)·cos(π/n + φ),
/// R = a / (2 sin(π/n)). 0 when no such height exists (φ ≥ π/2 − π/n).
ORI_API double ori_kresling_bistable_height(int sides, double width, double angle_rad);

#ifdef __cplusplus
}
#endif

#endif
