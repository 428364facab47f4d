/// orikin collision: self-collision of a folded sheet (SPEC capability 11, thesis ch. 5.4). One
/// state — faces as planar polygons (convex or not) at world vertex positions — is checked
/// exactly: every pair of faces that penetrate, every pair that only touch, and the minimum
/// clearance between faces that share no vertex, with witness points. Along a motion (a fold or
/// a whole sequence) every step is checked and the first contact is located by bisection on the
/// drive angle. The thesis' approximate "cloud of proximity" (sample points closer than a
/// distance) is kept as a cross-check. docs/collision.md has the semantics and the algorithms.
///
/// Functions: ori_default_collider_def, ori_collider_create, ori_collider_destroy,
/// ori_collider_face_count, ori_collider_vertex_count, ori_collider_adjacent,
/// ori_collider_check, ori_collider_contact_count, ori_collider_contact,
/// ori_default_cloud_def, ori_collider_cloud, ori_collider_cloud_pair_count,
/// ori_collider_cloud_pair, ori_default_collision_motion_def, ori_collision_check_motion,
/// ori_collision_check_record, ori_collision_check_multifold, ori_collision_check_trajectory.
///
/// Semantics. Faces that share a vertex (FOLD index), and so faces that share a crease, meet
/// there by construction: that is never a contact. They are still checked away from the shared
/// vertices: two faces of a vertex that cross each other penetrate, a flap folded flat onto its
/// neighbour touches it. Zero-thickness layers stacked in one plane (±180°) touch; a face passing
/// through another penetrates, and so does a stacked layer leaving its stack through a layer it
/// was below or above (the motion checks remember the order of stacked layers). Every length
/// tolerance is relative to the pattern's size (tolerance.h, ORI_TOL_CONTACT_REL and below).
#ifndef ORIKIN_COLLISION_H
#define ORIKIN_COLLISION_H

#include "base.h"
#include "kinematics.h"
#include "math.h"
#include "pattern.h"
#include "sequence.h"
#include "trajectory.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Creation parameters; get them from ori_default_collider_def().
typedef struct ori_collider_def {
    const ori_pattern *pattern; ///< built pattern: a flat crease pattern or a folded form; its faces_vertices are copied
    double clearance;           ///< ≥ 0, pattern length units: faces sharing no vertex that come closer than this collide too
    int internal_value;         ///< set by ori_default_collider_def; do not change
} ori_collider_def;

/// Defaults: no pattern (set one), clearance 0 (only penetration collides).
ORI_API ori_collider_def ori_default_collider_def(void);

/// Opaque collision checker of one pattern's faces; it holds the contacts of the last check.
typedef struct ori_collider ori_collider;

/// Build the checker: faces, which faces share vertices, convex pieces of non-convex faces.
/// Fails with ORI_ERR_RANGE for a negative or non-finite clearance, ORI_ERR_TOPOLOGY when the
/// pattern has no faces, ORI_ERR_DEGENERATE (field faces_vertices, element = face) for a face
/// that cannot be split into triangles. Destroy with ori_collider_destroy.
ORI_API ori_status ori_collider_create(const ori_collider_def *def, ori_collider **out, ori_error *error);
/// Destroy a checker; NULL is a no-op.
ORI_API void ori_collider_destroy(ori_collider *collider);
/// Number of faces (those of the pattern, FOLD indices).
ORI_API int ori_collider_face_count(const ori_collider *collider);
/// Number of vertices a state gives positions for.
ORI_API int ori_collider_vertex_count(const ori_collider *collider);
/// True when faces f and g (f ≠ g) share a vertex (and so meet there by construction).
ORI_API bool ori_collider_adjacent(const ori_collider *collider, int f, int g);

/// How two faces meet.
typedef enum ori_contact_kind {
    ORI_CONTACT_TOUCHING = 0, ///< in contact without crossing: an edge or vertex on the other face, stacked layers
    ORI_CONTACT_PENETRATING,  ///< the faces cross each other (or a stacked layer passed through another)
    ORI_CONTACT_NEAR,         ///< closer than the clearance, not touching (only with clearance > 0)
} ori_contact_kind;

/// One pair of faces in contact (or nearer than the clearance).
typedef struct ori_contact {
    int face_a, face_b;    ///< FOLD face indices, face_a < face_b
    ori_contact_kind kind;
    bool adjacent;         ///< the faces share a vertex: the contact is away from it
    bool stacked;          ///< coplanar layers overlapping by area (touching, or penetrating by order)
    bool collides;         ///< penetrating, or sharing no vertex and nearer than the clearance
    double distance;       ///< exact distance for NEAR (length), 0 for TOUCHING and PENETRATING
    ori_v3 point;          ///< witness (world): on the crossing, in the overlap, or midway between the closest points
} ori_contact;

/// Summary of one state's check (contacts by index with ori_collider_contact).
typedef struct ori_collision_result {
    bool collides;               ///< some face pair penetrates, or faces sharing no vertex are nearer than the clearance
    int penetrating;             ///< number of penetrating pairs
    int touching;                ///< number of touching pairs
    int near;                    ///< number of NEAR pairs
    int contact_count;           ///< penetrating + touching + near
    double min_clearance;        ///< least distance between faces sharing no vertex (0 when any touch); INFINITY when no such pair exists
    int clearance_faces[2];      ///< the pair at min_clearance, ORI_NULL_INDEX when none
    ori_v3 clearance_points[2];  ///< closest points on clearance_faces[0] and [1]
    bool has_witness;            ///< false only when nothing collides and no pair shares no vertex
    ori_v3 witness;              ///< the first colliding contact's point, else midway between clearance_points
    double tolerance;            ///< contact tolerance used for this state (length)
    int64_t candidate_pairs;     ///< broad-phase pairs (overlapping face boxes) given to the exact test
    int64_t distance_pairs;      ///< exact face–face distances computed (both phases)
} ori_collision_result;

/// Check one state: positions are the world coordinates of every vertex (vertex_count entries),
/// e.g. ori_mechanism_vertex_positions or a folded form's vertices_coords. Fails with
/// ORI_ERR_RANGE (field vertices_coords) for a non-finite coordinate, ORI_ERR_DEGENERATE (field
/// faces_vertices, element = face) for a face without area or off its plane by more than
/// ORI_TOL_FACE_PLANAR_REL × the pattern's diagonal. Contacts stay in the checker until its
/// next check.
ORI_API ori_status ori_collider_check(ori_collider *collider, const ori_v3 *positions,
                                      ori_collision_result *out, ori_error *error);
/// Number of contacts of the last check (sorted by face_a, then face_b).
ORI_API int ori_collider_contact_count(const ori_collider *collider);
/// A contact of the last check by value.
ORI_API ori_contact ori_collider_contact(const ori_collider *collider, int index);

// --- cloud of proximity (thesis ch. 5.4) ----------------------------------------------

/// Parameters of the cloud of proximity; get them from ori_default_cloud_def().
typedef struct ori_cloud_def {
    double spacing;     ///< > 0: sample spacing on every face (length)
    double distance;    ///< > 0: point pairs closer than this are reported (length)
    int64_t max_points; ///< more samples than this fail with ORI_ERR_LIMIT
    int internal_value; ///< set by ori_default_cloud_def; do not change
} ori_cloud_def;

/// Defaults: no spacing or distance (set both), at most ORI_CLOUD_MAX_POINTS samples.
ORI_API ori_cloud_def ori_default_cloud_def(void);

/// Most sample points of a cloud by default.
#define ORI_CLOUD_MAX_POINTS ((int64_t)1 << 25)

/// The closest sample pair of two faces within the cloud distance.
typedef struct ori_cloud_pair {
    int face_a, face_b;   ///< face_a < face_b, sharing no vertex
    int64_t point_pairs;  ///< sample pairs of these faces closer than the distance
    double distance;      ///< least sample distance
    ori_v3 points[2];     ///< the samples on face_a and face_b
} ori_cloud_pair;

/// Summary of a cloud.
typedef struct ori_cloud_result {
    int64_t points;        ///< samples on all faces
    int64_t point_pairs;   ///< sample pairs of faces sharing no vertex closer than the distance
    int face_pairs;        ///< face pairs with such samples (ori_collider_cloud_pair)
    double min_distance;   ///< least such sample distance, INFINITY when none
} ori_cloud_result;

/// The thesis' approximate method: sample every face (its vertices, its edges and a grid inside
/// it, all at most spacing apart) and find the sample pairs of faces sharing no vertex closer
/// than distance. min_distance ≥ the exact clearance and exceeds it by at most about the
/// spacing. Fails with ORI_ERR_RANGE for a spacing or distance that is not positive, and as
/// ori_collider_check for bad positions. Pairs stay in the checker until its next cloud.
ORI_API ori_status ori_collider_cloud(ori_collider *collider, const ori_v3 *positions, const ori_cloud_def *def,
                                      ori_cloud_result *out, ori_error *error);
/// Number of face pairs of the last cloud (sorted by face_a, then face_b).
ORI_API int ori_collider_cloud_pair_count(const ori_collider *collider);
/// A face pair of the last cloud by value.
ORI_API ori_cloud_pair ori_collider_cloud_pair(const ori_collider *collider, int index);

// --- along a motion ----------------------------------------------------------------------

/// Parameters of a motion check; get them from ori_default_collision_motion_def().
typedef struct ori_collision_motion_def {
    double drive_tol_rad;       ///< > 0: the first contact is located to this (radians of the drive)
    ori_progress_fn *progress;  ///< called with the fraction of frames checked, may be NULL
    void *progress_user;
    int internal_value;         ///< set by ori_default_collision_motion_def; do not change
} ori_collision_motion_def;

/// Defaults: ORI_TOL_CONTACT_DRIVE_RAD (1e-6°), no progress callback.
ORI_API ori_collision_motion_def ori_default_collision_motion_def(void);

/// The first collision along a motion.
typedef struct ori_collision_event {
    bool collides;        ///< false: every frame is clean (the fields below are unset)
    int frame;            ///< first colliding frame (motion or record frame); frames 0 … frame−1 are clean
    int fold;             ///< record: fold (0-based) of that frame; motion: 0
    int step;             ///< record: output step within that fold (1 = its first step, 0 = the start state); motion: = frame
    double drive_rad;     ///< drive angle at first contact, within drive_tol_rad after the true contact
    double time;          ///< record: sequence time at first contact; motion: the frame fraction frame − 1 + s
    ori_contact contact;  ///< the colliding pair and its witness at first contact
    int states_solved;    ///< intermediate states solved (half steps of the sweep check and the bisection)
} ori_collision_event;

/// Check a solved fold frame by frame; def is the fold it was solved with (driven crease, locks,
/// solver). Steps whose swept faces could meet in between are checked in halves
/// (docs/collision.md); the first contact is found by bisection on the drive angle, each trial
/// state solved with ori_motion_solve from the last clean state. Fails when a trial state cannot be solved or a state is bad (as
/// ori_collider_check); the collider then holds the contacts of the colliding state.
ORI_API ori_status ori_collision_check_motion(ori_collider *collider, const ori_mechanism *mechanism,
                                              const ori_motion_def *def, const ori_motion *motion,
                                              const ori_collision_motion_def *check, ori_collision_event *out,
                                              ori_error *error);
/// Check a recorded sequence frame by frame, states between frames restored with
/// ori_record_at (bisection on the sequence time until the drive bracket is below
/// drive_tol_rad). As ori_collision_check_motion otherwise.
ORI_API ori_status ori_collision_check_record(ori_collider *collider, const ori_record *record,
                                              const ori_collision_motion_def *check, ori_collision_event *out,
                                              ori_error *error);
/// Check a fold with several degrees of freedom (ori_target_fold_solve, ori_drives_fold_solve)
/// frame by frame; locked_edges (locked_count entries, may be NULL when 0) are the creases it held.
/// The bisection parameter is the frame progress (0 … 1): the event's drive_rad and time are the
/// progress at first contact (within drive_tol_rad), a state between frames their angles
/// interpolated and closed onto the loop-closure manifold. As ori_collision_check_motion otherwise.
ORI_API ori_status ori_collision_check_multifold(ori_collider *collider, const ori_multifold *fold,
                                                 const int *locked_edges, int locked_count,
                                                 const ori_collision_motion_def *check, ori_collision_event *out,
                                                 ori_error *error);
/// Check any motion result through its trajectory view (trajectory.h): a fold as
/// ori_collision_check_motion, a multifold as ori_collision_check_multifold, a sequence as
/// ori_collision_check_record (the three are this function on ori_trajectory_of_*). The view and
/// what it points at are borrowed.
ORI_API ori_status ori_collision_check_trajectory(ori_collider *collider, const ori_trajectory *trajectory,
                                                  const ori_collision_motion_def *check, ori_collision_event *out,
                                                  ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
