/// orikin fab: the fabrication files of a crease pattern (SPEC capability 21). A lithography
/// layout (panels shrunk by the hinge gap, hinge metal strips, the actuation wires with their
/// pads, alignment marks, a label) written as a GDSII stream, and cutting files for laser
/// cutters and plotters (DXF R12 with CUT / MOUNTAIN / VALLEY layers, an SVG with dashed or
/// perforated creases); and the fabrication tolerance of a fold: the distribution of its final
/// pose's error over seeded random perturbations of the pattern. docs/fabrication.md has the
/// layers and the conventions.
///
/// Functions: ori_default_fab_def, ori_fab_layout_create, ori_fab_layout_destroy,
/// ori_fab_layer_name, ori_fab_layer_description, ori_fab_shape_count, ori_fab_shape_at,
/// ori_fab_layout_meters_per_unit, ori_default_gds_def, ori_gds_real8, ori_gds_write,
/// ori_fab_layer_map, ori_default_cut_def, ori_dxf_write, ori_cut_svg_write, ori_crease_dashes,
/// ori_default_tolerance_def, ori_tolerance_run, ori_tolerance_destroy, ori_tolerance_sample_count,
/// ori_tolerance_sample_at, ori_tolerance_failed_count, ori_tolerance_nominal_current,
/// ori_tolerance_contact_count,
/// ori_tolerance_stats_of, ori_tolerance_sample_metric.
///
/// Coordinates: pattern units (the file's frame_unit) with y up, as in FOLD; GDSII and DXF keep
/// y up, the SVG flips it (y down) as every SVG writer of orikin does.
#ifndef ORIKIN_FAB_H
#define ORIKIN_FAB_H

#include <stdint.h>

#include "actuation.h"
#include "kinematics.h"
#include "base.h"
#include "math.h"
#include "pattern.h"
#include "tolerance.h"

#ifdef __cplusplus
extern "C" {
#endif

// --- the lithography layout ----------------------------------------------------------------

/// Layers of a layout; the value is the GDSII layer number (datatype 0).
typedef enum ori_fab_layer {
    ORI_FAB_PANEL = 1, ///< panels: each face shrunk by half the hinge gap along its creases
    ORI_FAB_HINGE = 2, ///< hinge metal: a strip per crease with a hinge, centred on the crease
    ORI_FAB_WIRE = 3,  ///< actuation wires: per wired hinge a path (leg, wire, leg) on its panel and two leads
    ORI_FAB_PAD = 4,   ///< contact pads at the ends of the leads
    ORI_FAB_MARK = 5,  ///< alignment marks (crosses) outside the four corners of the sheet
    ORI_FAB_LABEL = 6, ///< a text label below the sheet
} ori_fab_layer;

/// Lowest and highest layer numbers.
#define ORI_FAB_LAYER_FIRST ORI_FAB_PANEL
#define ORI_FAB_LAYER_LAST ORI_FAB_LABEL

/// Upper-case name of a layer ("PANEL"); "?" for another value. Static string.
ORI_API const char *ori_fab_layer_name(int layer);
/// One-line description of a layer (what is drawn on it). Static string.
ORI_API const char *ori_fab_layer_description(int layer);

/// Longest label (bytes, including the terminating NUL).
#define ORI_FAB_LABEL_MAX 128

/// Layout parameters; get them from ori_default_fab_def(). Lengths in metres.
typedef struct ori_fab_def {
    const ori_pattern *pattern;   ///< built flat crease pattern (frame 0)
    const ori_design *design;     ///< hinges, wires and the length unit (edges_orikin:hinge); may be NULL
    double meters_per_unit;       ///< metres per pattern unit (> 0); ignored when design is given (its unit)
    int fixed_face;               ///< the face held while folding: a wire without a face of its own goes on the other side of its crease; ORI_NULL_INDEX = ori_pattern_center_face
    double hinge_gap_m;           ///< gap between the panels across a crease; ≤ 0 (default): each hinge's span, else default_hinge_span_m
    double default_hinge_span_m;  ///< gap of creases without hinge data (default 20 µm)
    double hinge_overlap_m;       ///< how far a hinge strip reaches onto each panel beyond the gap (default 10 µm)
    double hinge_width_m;         ///< > 0: every hinge strip this wide along its crease (overrides the design); ≤ 0: the design's width, and for creases without hinge data the crease's length less the gap at each end
    bool hinges_everywhere;       ///< strips on creases without hinge data too (default true); false: only where the design has a hinge
    double wire_width_m;          ///< > 0: every wire's trace width; ≤ 0 (default): the wire's own conductor width (the design's default: the hinge's width)
    double pad_size_m;            ///< side of a square contact pad (default 100 µm)
    double lead_length_m;         ///< length of a lead from the crease to its pad on the other panel (default 150 µm)
    double mark_size_m;           ///< arm length of an alignment cross (default 100 µm); its arms are a tenth as wide
    double mark_margin_m;         ///< distance of the marks' centres from the sheet's bounding box (default 200 µm)
    double label_height_m;        ///< text height (default 100 µm)
    char label[ORI_FAB_LABEL_MAX]; ///< label text (default "orikin")
    int internal_value;           ///< set by ori_default_fab_def; do not change
} ori_fab_def;

/// Defaults: see the fields (the thesis device: 20 µm gaps, 100 µm pads and marks).
ORI_API ori_fab_def ori_default_fab_def(void);

/// Kinds of shapes.
typedef enum ori_fab_shape_kind {
    ORI_FAB_POLYGON = 0, ///< a closed polygon, counter-clockwise, first point not repeated
    ORI_FAB_PATH = 1,    ///< an open polyline of a width (square ends flush with the end points)
    ORI_FAB_TEXT = 2,    ///< a text anchored at its one point (lower left)
} ori_fab_shape_kind;

/// A shape of a layout, in pattern units.
typedef struct ori_fab_shape {
    int layer;                ///< ori_fab_layer
    ori_fab_shape_kind kind;
    int element;              ///< the face (PANEL) or edge (HINGE, WIRE, PAD) it belongs to; ORI_NULL_INDEX otherwise
    int point_count;
    const ori_v2 *points;     ///< owned by the layout
    double width;             ///< PATH: its width; TEXT: its height; 0 otherwise
    const char *text;         ///< TEXT: the string (owned by the layout); NULL otherwise
} ori_fab_shape;

/// Opaque layout: a list of shapes.
typedef struct ori_fab_layout ori_fab_layout;

/// Build the layout of a flat pattern: per face the panel polygon (its edges that are creases
/// moved inward by half the gap), per crease the hinge strip, per wired hinge the wire path on
/// its panel (legs at the ends of the wire, perpendicular to the crease, and the wire at its
/// lever), two leads across the crease onto the other panel and a pad at each, four alignment
/// crosses and the label. Fails with ORI_ERR_ARGUMENT (no pattern, not built, folded, no unit),
/// ORI_ERR_RANGE (a negative or non-finite length, or one beyond the range of lengths in the
/// pattern's unit: field names it; a shape beyond the range of coordinates) and ORI_ERR_DEGENERATE
/// (element = the face) when a gap this wide leaves a panel with no area. Destroy with ori_fab_layout_destroy.
ORI_API ori_status ori_fab_layout_create(const ori_fab_def *def, ori_fab_layout **out, ori_error *error);
/// Destroy a layout; NULL is a no-op.
ORI_API void ori_fab_layout_destroy(ori_fab_layout *layout);
/// Number of shapes (panels first in face order, then hinges, wires, pads, marks, the label).
ORI_API int ori_fab_shape_count(const ori_fab_layout *layout);
/// A shape by index; its pointers stay valid while the layout lives.
ORI_API ori_fab_shape ori_fab_shape_at(const ori_fab_layout *layout, int index);
/// Metres per pattern unit of the layout.
ORI_API double ori_fab_layout_meters_per_unit(const ori_fab_layout *layout);

// --- GDSII ---------------------------------------------------------------------------------

/// GDSII writing parameters; get them from ori_default_gds_def().
typedef struct ori_gds_def {
    double user_unit_m;       ///< the user unit (≤ 0: the pattern unit, default)
    double database_unit_m;   ///< the database unit, the grid every coordinate is rounded to (≤ 0: user unit / 1000, default)
    const char *library_name; ///< LIBNAME (default "ORIKIN")
    const char *cell_name;    ///< STRNAME of the one cell (default "DEVICE")
    int internal_value;       ///< set by ori_default_gds_def; do not change
} ori_gds_def;

/// Defaults: the pattern unit as user unit, a thousandth of it as database unit (nm for µm).
ORI_API ori_gds_def ori_default_gds_def(void);

/// The 8-byte excess-64 base-16 real of GDSII (sign bit, 7-bit exponent, 56-bit mantissa,
/// big-endian) of a finite x, into out[8]. Exact for every double in its range (the 53-bit
/// significand fits the 56-bit mantissa); 0 for |x| < 16^-65 (underflow), false when |x| ≥ 16^63.
ORI_API bool ori_gds_real8(double x, unsigned char out[8]);

/// The layout as a GDSII stream (version 600): HEADER, BGNLIB, LIBNAME, UNITS, one cell with a
/// BOUNDARY per polygon, a PATH per path (PATHTYPE 0, WIDTH), a TEXT per text, on the layer
/// numbers of ori_fab_layer, datatype 0; dates 1970-01-01 so that the bytes depend on the input
/// only. Coordinates are rounded to the database unit. Fails (NULL, error set) with ORI_ERR_LIMIT
/// for a coordinate beyond ±2^31 database units, a polygon of more than 8190 points or a library
/// or cell name of more than 65530 bytes (what a record holds), and with ORI_ERR_RANGE (field
/// "units") for a user or database unit, or a text height, that GDSII reals cannot hold (beyond
/// 16^63, or nonzero below 16^-65, which would be written as 0).
/// *size receives the byte count; free with ori_buffer_free.
ORI_API unsigned char *ori_gds_write(const ori_fab_layout *layout, const ori_gds_def *def, size_t *size,
                                     ori_error *error);
/// The layer map of a layout: "# comments", then per layer "NUMBER/DATATYPE NAME description"
/// (the form KLayout's layer-mapping reads as "1/0 PANEL"). Free with ori_buffer_free.
ORI_API char *ori_fab_layer_map(const ori_fab_layout *layout);

// --- cutting files -------------------------------------------------------------------------

/// Cutting-file parameters; get them from ori_default_cut_def(). Lengths in output millimetres.
typedef struct ori_cut_def {
    double mm_per_unit;   ///< millimetres per pattern unit (> 0; default 1)
    double dash_mm;       ///< SVG: length of a crease's dashes (default 3)
    double gap_mm;        ///< SVG: gap between dashes (default 1.5)
    double vertex_gap_mm; ///< SVG: a crease's dashes stop this far from each of its end vertices (default 1)
    bool perforate;       ///< SVG: creases as perforations (cut-through slits of perforation_mm every perforation_pitch_mm) instead of dashes
    double perforation_mm;       ///< slit length (default 0.5)
    double perforation_pitch_mm; ///< slit start to slit start (default 1.5)
    double stroke_mm;     ///< SVG: stroke width (default 0.1, a hairline for most laser drivers)
    int internal_value;   ///< set by ori_default_cut_def; do not change
} ori_cut_def;

/// Defaults: 1 mm per unit, 3 mm dashes with 1.5 mm gaps stopping 1 mm from the vertices.
ORI_API ori_cut_def ori_default_cut_def(void);

/// Most dashes (or slits) of one crease.
#define ORI_CUT_MAX_DASHES 1000000

/// The dashes of a crease of length length_mm (all in mm, measured from its first vertex) into
/// starts[i], ends[i] (cap entries): the stretch [vertex_gap, length − vertex_gap] filled with n =
/// ⌊(stretch + gap) / (dash + gap)⌋ dashes separated by gap, centred (the left-over split
/// between the ends); one dash over the whole stretch when it is shorter than a dash; none when
/// the crease is shorter than two vertex gaps. With perforate the slits and pitch replace dash
/// and dash + gap. Returns the count (which may exceed cap: only cap are written); −1 when def
/// is out of range (as ori_cut_svg_write checks it) or the count would exceed ORI_CUT_MAX_DASHES.
ORI_API int ori_crease_dashes(double length_mm, const ori_cut_def *def, double *starts, double *ends, int cap);

/// The flat pattern as an ASCII DXF (R12, AC1009): layers CUT (B and C edges, colour 7),
/// MOUNTAIN (colour 1, red), VALLEY (colour 5, blue) and UNASSIGNED (U, colour 3); F and J
/// edges are not written. One LINE per edge in edge order, whole (the cutter's driver dashes
/// or scores a layer as it is set up), coordinates in mm, y up, $INSUNITS 4 (mm). def NULL: the
/// defaults. Free with ori_buffer_free. Fails (NULL, error set) with ORI_ERR_ARGUMENT when the
/// pattern is not flat, ORI_ERR_RANGE when mm_per_unit is not a finite number > 0 or puts the
/// pattern beyond the range of coordinates.
ORI_API char *ori_dxf_write(const ori_pattern *pattern, const ori_cut_def *def, ori_error *error);
/// The flat pattern as an SVG for laser cutters, in mm (width/height in mm, viewBox in mm, y
/// down): a group (an Inkscape layer) per kind: "cut" (B, C: solid black lines), "mountain"
/// (red) and "valley" (blue) with each crease as its dashes (ori_crease_dashes) or
/// perforations, "unassigned" (U, green dashes); F and J edges are left out. Every dash is its
/// own <line> (laser drivers ignore stroke-dasharray). Free with ori_buffer_free. Fails (NULL,
/// error set) as ori_dxf_write, and with ORI_ERR_RANGE (field named) for a dash, slit or stroke
/// that is not a finite length > 0, a gap or vertex gap not finite ≥ 0, a pitch not longer than
/// its slit (the fields of the style asked for: dash and gap, or slit and pitch), ORI_ERR_LIMIT
/// (element = the edge) for a crease of more than ORI_CUT_MAX_DASHES dashes.
ORI_API char *ori_cut_svg_write(const ori_pattern *pattern, const ori_cut_def *def, ori_error *error);

// --- fabrication tolerance -----------------------------------------------------------------

/// Most samples of one analysis.
#define ORI_TOLERANCE_MAX_SAMPLES 100000000

/// A tolerance analysis; get it from ori_default_tolerance_def().
typedef struct ori_tolerance_def {
    const ori_pattern *pattern;    ///< built flat crease pattern (the nominal design)
    const ori_motion_def *motion;  ///< the fold every sample makes (fixed face, drive, target, locks, start angles);
                                   ///< copied; last_frame_only and progress are set by the analysis
    double vertex_sigma;           ///< standard deviation of each vertex coordinate (x and y independently), pattern units (≥ 0)
    int samples;                   ///< number of perturbed samples (1 … ORI_TOLERANCE_MAX_SAMPLES)
    uint64_t seed;                 ///< the random stream: the same seed gives the same samples (sample k's draws depend on seed and k only)
    int threads;                   ///< worker threads (≤ 1: the calling thread only); the results do not depend on it
    const ori_design_def *design;  ///< NULL, or the design (hinges, wires, field) to size every sample's fold with (ori_sizing_solve,
                                   ///< the design's schedule rules): the current it needs is a metric; its pattern field is ignored (the
                                   ///< nominal pattern's panel masses and wire places are used for every sample)
    double width_sigma_rel;        ///< with design: each hinge's width × (1 + this × a normal deviate), drawn after the vertices (≥ 0)
    ori_progress_fn *progress;     ///< called after each sample (from the calling thread) with the fraction done; may be NULL;
                                   ///< returning false cancels: ORI_ERR_LIMIT ("cancelled"), nothing out
    void *progress_user;
    int internal_value;            ///< set by ori_default_tolerance_def; do not change
} ori_tolerance_def;

/// Defaults: no pattern or fold (set them), σ = 0, 100 samples, seed 1, one thread.
ORI_API ori_tolerance_def ori_default_tolerance_def(void);

/// The errors of one sample's final pose against the nominal one (the fixed face's frame: the
/// fixed face is held where the flat sheet has it in both).
typedef struct ori_tolerance_sample {
    bool folded;              ///< the sample built and folded to the end (a valid motion); the errors below are meaningful only then
    double position_error;    ///< largest distance of a vertex from its nominal final position (pattern units)
    double end_effector_error;///< single-vertex folds: distance of the end effector (Frame B's free vertex, in Frame A) from its nominal; 0 otherwise
    double normal_error_rad;  ///< largest angle between a face's normal and its nominal
    double angle_error_rad;   ///< largest |fold angle − nominal| over the creases
    double gap;               ///< largest distance between two vertices that meet in the nominal final state (pattern units; 0 when none meet)
    double current_a;         ///< with a design: the largest current a wire needs along the sample's fold (A; INFINITY when the field cannot drive it); 0 otherwise
} ori_tolerance_sample;

/// The metrics of a sample, for ori_tolerance_stats_of.
typedef enum ori_tolerance_metric {
    ORI_TOLERANCE_METRIC_POSITION = 0,
    ORI_TOLERANCE_METRIC_END_EFFECTOR,
    ORI_TOLERANCE_METRIC_NORMAL,
    ORI_TOLERANCE_METRIC_ANGLE,
    ORI_TOLERANCE_METRIC_GAP,
    ORI_TOLERANCE_METRIC_CURRENT,
    ORI_TOLERANCE_METRIC_COUNT
} ori_tolerance_metric;

/// Distribution of a metric over the samples that folded.
typedef struct ori_tolerance_stats {
    int count;                   ///< samples that folded
    double mean, sd;             ///< mean and sample standard deviation (0 for one sample)
    double min, max;
    double p50, p90, p95, p99;   ///< percentiles (linear interpolation between order statistics)
} ori_tolerance_stats;

/// Opaque result of an analysis.
typedef struct ori_tolerance ori_tolerance;

/// Fold the nominal pattern, then `samples` copies of it with every vertex moved by a normal
/// deviate of σ in x and in y (seeded: splitmix64 per sample, Box–Muller), each folded with the
/// same motion (ori_motion_solve, rigid), and compare each final pose with the nominal one.
/// A sample whose perturbed pattern does not build or whose fold is not valid is counted as
/// not folded. With a design each sample's hinges get perturbed widths and its fold is sized (a
/// width that the draw makes ≤ 0 fails the sample). Fails with ORI_ERR_RANGE (σ, samples),
/// ORI_ERR_ARGUMENT (the nominal fold is not valid: its reason in the message), the design's or
/// the nominal sizing's error, or the motion's error. Destroy with ori_tolerance_destroy.
ORI_API ori_status ori_tolerance_run(const ori_tolerance_def *def, ori_tolerance **out, ori_error *error);
/// Destroy an analysis; NULL is a no-op.
ORI_API void ori_tolerance_destroy(ori_tolerance *tolerance);
/// Number of samples.
ORI_API int ori_tolerance_sample_count(const ori_tolerance *tolerance);
/// A sample by index, by value.
ORI_API ori_tolerance_sample ori_tolerance_sample_at(const ori_tolerance *tolerance, int index);
/// Samples that did not fold.
ORI_API int ori_tolerance_failed_count(const ori_tolerance *tolerance);
/// With a design: the current the nominal fold needs (A); 0 without.
ORI_API double ori_tolerance_nominal_current(const ori_tolerance *tolerance);
/// Vertex pairs that meet in the nominal final state (the gap metric's pairs).
ORI_API int ori_tolerance_contact_count(const ori_tolerance *tolerance);
/// The distribution of a metric over the samples that folded (all zero when none did).
ORI_API ori_tolerance_stats ori_tolerance_stats_of(const ori_tolerance *tolerance, ori_tolerance_metric metric);
/// A metric of a sample.
ORI_API double ori_tolerance_sample_metric(const ori_tolerance_sample *sample, ori_tolerance_metric metric);

#ifdef __cplusplus
}
#endif

#endif
