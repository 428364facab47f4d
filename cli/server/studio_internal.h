// Shared pieces of the studio's server files: the document state, reference-counted models
// and results, request helpers, and the JSON builders that mirror the CLI's --json outputs.
#ifndef ORI_STUDIO_INTERNAL_H
#define ORI_STUDIO_INTERNAL_H

#include <jansson.h>
#include <orikin/orikin.h>
#include <pthread.h>
#include <stdatomic.h>

#include "report.h"
#include "studio.h"

// Longest file label or path the server keeps.
#define STUDIO_PATH_MAX 1024
// Most creases one fold may lock (as the CLI's --lock).
#define STUDIO_MAX_LOCKS 256
// Sequence time: a request within this of a state of the scrubbing cache is answered by that
// state (exact: solved on the fine grid, not interpolated). Sequence-time units (folds).
#define STUDIO_TIME_SNAP 1e-12

// --- models: an immutable built crease pattern and its mechanism -------------------------

// A document state. The pattern never changes once the model exists (edits make a new model),
// so computations hold a reference and run without the document lock.
typedef struct studio_model {
    atomic_int refs;
    ori_pattern *pattern;        // built flat crease pattern (frame 0)
    pthread_mutex_t lock;        // guards the lazy mechanism
    ori_mechanism *mech;         // created on first use
    bool mech_tried;
    ori_error mech_error;
} studio_model;

studio_model *studio_model_new(ori_pattern *pattern); // takes ownership of pattern
studio_model *studio_model_ref(studio_model *m);
void studio_model_unref(studio_model *m);
// The mechanism of the model (created once), or NULL with the error.
const ori_mechanism *studio_model_mechanism(studio_model *m, ori_error *error);

// The state at the first contact of a motion that collides (the fold or sequence solved exactly
// at the event's drive angle or time): what GET /api/contact shows with the colliding faces.
typedef struct studio_contact {
    bool has;                // a contact state was solved
    double t;                // sequence time (a sequence) or frame fraction (a fold)
    int fold;                // 0-based fold of a sequence (0 for a fold)
    double drive_rad, residual;
    double *angles;          // edge_count
    ori_v3 *positions;       // vertex_count
} studio_contact;

void studio_contact_free(studio_contact *c);

// A sequence that ran on a model: the record the API reports, and the scrubbing cache (the
// same folds run again on a fine uniform time grid, every state exact).
typedef struct studio_seq {
    atomic_int refs;
    studio_model *model;
    ori_sequence *sequence;
    ori_record *record;
    ori_record *fine;        // NULL when there is no cache
    int grid;                // cache states per fold (0 without cache)
    char *json;              // the record's JSON (as orikin sequence --json)
    size_t json_size;
    cli_collision collision; // its self-collision check (as orikin sequence)
    studio_contact contact;  // the state at first contact when it collides
    pthread_mutex_t lock;    // one restore at a time per record
} studio_seq;

void studio_seq_unref(studio_seq *q);

// A fold computed on a model (POST /api/fold), kept for GET /api/fold/frame.
typedef struct studio_fold {
    atomic_int refs;
    studio_model *model;
    ori_motion *motion;      // a single-drive fold, or NULL
    ori_multifold *multi;    // else a fold mode (toward the targets, several drives, symmetric)
    ori_motion_def def;      // as solved (its arrays below are owned; a mode: fixed_face and fixed_pose)
    double *start_angles;
    int *locks;
    double start_drive_rad;  // where the drive starts (exports time the motion from it)
    cli_collision collision; // its self-collision check (as orikin fold)
    int clean_frames;        // frames before the first contact (all of them when clean)
    studio_contact contact;  // the state at first contact when it collides
} studio_fold;

void studio_fold_unref(studio_fold *f);

// One undo or redo step: the model to restore and, when the whole document was replaced (open,
// new sheet), that document with its label.
typedef struct studio_step {
    studio_model *model;
    ori_fold *doc;                // NULL: same document, only frame 0 changes
    char file[STUDIO_PATH_MAX];
    ori_format format;
    bool from_command_line;
} studio_step;

// What a file on disk was when the studio last read or wrote it (a changed file is one whose
// identity, size or modification time differs).
typedef struct studio_disk {
    bool known;
    unsigned long long dev, ino;
    long long size, mtime_sec, mtime_nsec;
} studio_disk;

struct studio {
    studio_def def;
    pthread_mutex_t lock;        // guards everything below but the job slot
    long version;
    ori_fold *doc;               // the FOLD document (unknown fields kept)
    studio_model *model;         // its frame 0
    char file[STUDIO_PATH_MAX];  // label: the path as given, or the dropped file's name
    ori_format format;           // format the document came from
    bool from_command_line;      // the document is the file given on the command line
    char save_path[STUDIO_PATH_MAX];    // where save-back writes the document ("" none)
    ori_format save_format;
    char seq_path[STUDIO_PATH_MAX];     // the SEQ.json given on the command line ("" none)
    char seq_pattern_ref[STUDIO_PATH_MAX]; // its "pattern" field as written
    studio_step undo[STUDIO_UNDO_DEPTH];
    int undo_count;
    studio_step redo[STUDIO_UNDO_DEPTH];
    int redo_count;
    studio_disk doc_disk;        // save_path as last read or written
    studio_disk seq_disk;        // seq_path likewise
    studio_model *saved_model;   // the state that is on disk (a reference; == model: nothing unsaved)
    char journal[STUDIO_PATH_MAX]; // the autosave beside save_path ("" none)
    bool recovery;               // a journal of an earlier session waits for recover or discard
    studio_seq *seq;             // the last sequence run on the current document
    studio_fold *fold;           // the last fold computed on the current document
    struct studio_cfold *compliant; // the last compliant fold solved on it (POST /api/compliant)

    pthread_mutex_t job_lock;    // the one long computation allowed at a time
    bool busy;
    char job[48];
    double job_start;
    double job_fraction;         // < 0: the running phase reports no fraction
};

// --- requests and responses ---------------------------------------------------------------

// Monotonic seconds.
double studio_now(void);
// Query argument by key, or NULL.
const char *studio_arg_get(const studio_request *req, const char *key);
// Replace the bytes of s that are not UTF-8 by '?' (JSON strings must be UTF-8).
void studio_utf8_clean(char *s);
// 400-style error: {"error": "one line"} (newlines replaced, valid UTF-8).
void studio_fail(studio_response *out, int status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
// An error of the library as {"error": ...} (ori_error_format).
void studio_fail_error(studio_response *out, int status, const ori_error *err);
// err formatted on one line (newlines become spaces) into buf (size bytes).
void studio_error_line(char *buf, size_t size, const ori_error *err);
// The status of a library failure: 500 for internal or non-convergence, else 400.
int studio_status_of(ori_status st);
// A JSON value (consumed) as the response body, numbers in their shortest exact form.
void studio_respond_json(studio_response *out, int status, json_t *value);
// A text body (copied).
void studio_respond_text(studio_response *out, int status, const char *content_type, const char *text, size_t size);
// JSON text in the CLI's form (compact, shortest exact numbers), malloc'd; consumes value.
char *studio_json_text(json_t *value, size_t *size);

// Parse a request body as a JSON object; on failure fills a 400 and returns NULL.
json_t *studio_body_object(const studio_request *req, studio_response *out);
// Reject fields of o not in keys (NULL-terminated): 400 "unknown field".
bool studio_check_keys(json_t *o, const char *const *keys, studio_response *out);
// Typed field readers: false after a 400 naming the field. Optional fields keep *out when
// absent (and set *present when given).
bool studio_get_int(json_t *o, const char *key, bool required, int *out, bool *present, studio_response *res);
bool studio_get_number(json_t *o, const char *key, bool required, double *out, bool *present, studio_response *res);
bool studio_get_bool(json_t *o, const char *key, bool *out, studio_response *res);
bool studio_get_string(json_t *o, const char *key, bool required, const char **out, studio_response *res);
bool studio_get_numbers(json_t *o, const char *key, bool required, double *out, int n, bool *present,
                        studio_response *res);
// An int list ([E, …]); *count set; false after a 400.
bool studio_get_int_list(json_t *o, const char *key, int *out, int cap, int *count, studio_response *res);

// The job slot: false (after a 409) when another long computation runs.
bool studio_job_begin(studio *s, const char *name, studio_response *out);
void studio_job_end(studio *s);
// A new phase of the running job ("checking collisions"): its name and no fraction yet.
void studio_job_phase(studio *s, const char *name);
// An ori_progress_fn whose user pointer is the studio: the running phase's fraction done.
bool studio_job_progress(double fraction, void *user);

// A new document state after a successful edit: push the current one on the undo stack, clear
// redo, install model (takes the reference) into the document, bump the version. Call locked.
void studio_commit(studio *s, studio_model *model);
// Replace the whole document (open, new sheet); takes doc and model. Call locked.
void studio_commit_document(studio *s, ori_fold *doc, studio_model *model, const char *file, ori_format format,
                            bool from_command_line);
// Drop results computed on an older document (sequence, fold). Call locked.
void studio_drop_results(studio *s);

// --- the file on disk and the autosave (studio_disk.c) ----------------------------------------

// Record what path is on disk now (known false when it cannot be stat'ed).
void studio_disk_remember(studio_disk *d, const char *path);
// Whether path changed on disk since studio_disk_remember (false when nothing was known).
bool studio_disk_changed(const studio_disk *d, const char *path);
// The autosave journal of a document saved to save_path: ".NAME.orikin-autosave" beside it.
void studio_journal_path(const char *save_path, char *out, size_t size);
// After a change of version: write the document to the journal (mode 0600) while it differs
// from the file on disk, remove the journal when it no longer does. Not while a recovery
// waits. Call locked; failures only leave the journal as it was.
void studio_autosave(studio *s);
// The document was written to save_path: it is what the disk holds now (journal removed).
void studio_mark_saved(studio *s);

// Build a flat pattern from an imported drawing or FOLD text: a new document and its model.
// name gives the format by extension; false with a one-line message.
bool studio_load_text(const char *name, const char *text, size_t size, ori_fold **doc, studio_model **model,
                      char *err, size_t err_size);

// The start state of a computation at a frame of the document: fold angles (edge_count) and
// vertex coordinates (vertex_count, malloc'd), folded when the frame is a folded form. Call
// locked (reads the document). False with a 400 on a bad frame.
bool studio_frame_state(studio *s, int frame, double **angles, ori_v3 **coords, bool *folded, studio_response *out);

// --- handlers (studio_author.c, studio_kin.c) ----------------------------------------------

void studio_api_session(studio *s, const studio_request *req, studio_response *out);
void studio_api_document(studio *s, const studio_request *req, studio_response *out);
void studio_api_tree(studio *s, const studio_request *req, studio_response *out);
void studio_api_info(studio *s, const studio_request *req, studio_response *out);
void studio_api_new(studio *s, const studio_request *req, studio_response *out);
void studio_api_open(studio *s, const studio_request *req, studio_response *out);
void studio_api_apply(studio *s, const studio_request *req, studio_response *out);
void studio_api_crease(studio *s, const studio_request *req, studio_response *out);
void studio_api_axiom(studio *s, const studio_request *req, studio_response *out);
void studio_api_edit(studio *s, const studio_request *req, studio_response *out);
void studio_api_undo(studio *s, const studio_request *req, studio_response *out);
void studio_api_recover(studio *s, const studio_request *req, studio_response *out);
void studio_api_redo(studio *s, const studio_request *req, studio_response *out);
void studio_api_save(studio *s, const studio_request *req, studio_response *out);
void studio_api_export(studio *s, const studio_request *req, studio_response *out);
void studio_api_check(studio *s, const studio_request *req, studio_response *out);
void studio_api_dof(studio *s, const studio_request *req, studio_response *out);
void studio_api_mechanism(studio *s, const studio_request *req, studio_response *out);
void studio_api_fold(studio *s, const studio_request *req, studio_response *out);
void studio_api_fold_frame(studio *s, const studio_request *req, studio_response *out);
void studio_api_sequence(studio *s, const studio_request *req, studio_response *out);
void studio_api_sequence_get(studio *s, const studio_request *req, studio_response *out);
void studio_api_sequence_at(studio *s, const studio_request *req, studio_response *out);
void studio_api_progress(studio *s, const studio_request *req, studio_response *out);
void studio_api_contact(studio *s, const studio_request *req, studio_response *out);
void studio_api_collide(studio *s, const studio_request *req, studio_response *out);
void studio_api_regularize(studio *s, const studio_request *req, studio_response *out);
void studio_api_compliant(studio *s, const studio_request *req, studio_response *out);
// GET /api/frames (studio_frames.c): a multi-frame document's states, times and vertex coordinates.
void studio_api_frames(studio *s, const studio_request *req, studio_response *out);

// How a motion is checked for self-collision (as the CLI's --no-collisions and --clearance D).
typedef struct studio_collide_opts {
    bool skip;
    double clearance;  // ≥ 0, pattern length units
} studio_collide_opts;

// Run a sequence on the current document and publish it (POST /api/sequence, and the SEQ.json
// given on the command line, whose path is label), checked for self-collision as opts says.
// seq is consumed. Fills out with the record JSON or an error.
void studio_run_sequence(studio *s, ori_sequence *seq, const char *label, const studio_collide_opts *opts,
                         studio_response *out);

// The collider of a flat pattern at a clearance: NULL after a 400 (a bad clearance named as the
// request field "clearance").
ori_collider *studio_collider(const ori_pattern *p, double clearance, studio_response *out);

// --- states (POST /api/collide, GET /api/export): which one, and the posed sheet -------------

// A state named by a request: a document frame, an instant of the sequence, a state of the
// computed fold, or the first contact of either.
typedef enum studio_state_kind {
    STUDIO_STATE_FRAME = 0, // frame (default 0)
    STUDIO_STATE_TIME,      // t: the sequence at time T
    STUDIO_STATE_FOLD,      // k: state k of the computed fold
    STUDIO_STATE_CONTACT,   // contact: "fold" or "sequence"
    STUDIO_STATE_COMPLIANT, // compliant=1: the end of the last compliant fold (GET /api/export)
} studio_state_kind;

// The last compliant fold solved on the document (POST /api/compliant), with its load steps: its
// end is a state (compliant=1) and its steps a motion (of=compliant) of GET /api/export.
typedef struct studio_cfold {
    atomic_int refs;
    studio_model *model;
    ori_compliant *c;
} studio_cfold;
void studio_cfold_unref(studio_cfold *f);
// The document's compliant fold (a reference: studio_cfold_unref), or NULL.
studio_cfold *studio_cfold_get(studio *s);

typedef struct studio_state_ref {
    studio_state_kind kind;
    int frame, k;
    double t;
    bool contact_of_sequence;
} studio_state_ref;

// Read frame / t / k / contact from the query arguments (at most one); false after a 400.
bool studio_state_ref_args(const studio_request *req, studio_state_ref *ref, studio_response *out);
// Read them from a JSON body's fields; false after a 400.
bool studio_state_ref_json(json_t *o, studio_state_ref *ref, studio_response *out);

// A posed sheet: the pattern to draw (topology and, when flat, the crease pattern) and where
// every vertex is, as orikin render / export / collide load it.
typedef struct studio_state {
    studio_model *model;     // the document's model (a reference)
    ori_pattern *own;        // a frame's own pattern, else NULL
    ori_mechanism *own_mech; // the mechanism of a crease-pattern frame other than 0, else NULL
    const ori_pattern *pattern;
    const ori_pattern *collide_pattern; // the faces collide checks: a folded frame's own (its size sets
                             // the contact tolerance, as orikin collide), else pattern
    bool has_flat;           // pattern is a flat crease pattern (the crease view, texture coordinates)
    bool cp_frame;           // a crease-pattern frame of the document (render draws its creases by default)
    bool posed;              // positions come from the kinematics (else a folded form's coordinates)
    bool folded;             // not the flat sheet
    int frame;               // the document frame, or -1
    ori_v3 *positions;       // vertex_count, or NULL (an unposed crease-pattern frame)
    double *angles;          // edge_count radians, or NULL
    ori_rigid *poses;        // face_count, or NULL
    char label[96];          // "frame 0", "t = 1.5", "fold state 4", "contact of the fold"
} studio_state;

// Load the state ref names (need_pose: also pose a crease-pattern frame from its fold angles, as
// render's 3D view and collide do). False after an error response.
bool studio_state_load(studio *s, const studio_state_ref *ref, bool need_pose, studio_state *st, studio_response *out);
void studio_state_free(studio_state *st);

// The export formats (GET /api/export?format=…): one table entry per format.
typedef enum studio_export_kind {
    STUDIO_EXPORT_DOCUMENT = 0, // the document or its crease pattern (fold, svg, cp, opx)
    STUDIO_EXPORT_PICTURE,      // a picture of a state (orikin render): png, pdf, svg-picture
    STUDIO_EXPORT_MESH,         // a mesh of a state (orikin export): obj, stl, ply, gltf, glb
    STUDIO_EXPORT_ANIMATION,    // a motion only (orikin animate): gif
} studio_export_kind;

typedef struct studio_export_format {
    const char *name;       // "fold", "svg", "png", …
    const char *label;      // menu text
    const char *extension;  // ".fold"
    const char *mime;
    studio_export_kind kind;
    bool motion;            // can hold a whole motion (of=sequence or of=fold)
    int render_format;      // ori_image_format or ori_mesh_format (pictures and meshes)
} studio_export_format;
int studio_export_format_count(void);
const studio_export_format *studio_export_format_at(int i);
// The document's file name with another extension ("open-corner.png"), safe in a header.
void studio_download_name(const char *file, const char *ext, char *out, size_t size);
// GET /api/export of a picture, mesh or animation (studio_render.c): the state named by the
// arguments (frame, t, k, contact) or, with of=sequence / of=fold, the whole motion.
void studio_export_render(studio *s, const studio_request *req, const studio_export_format *f, studio_response *out);

// --- JSON builders: field for field what the CLI prints with --json -----------------------

// What `orikin fold` was asked (the echo fields of its JSON).
typedef struct studio_fold_spec {
    int fix, drive;
    double to_deg, step_deg, from_deg;
    bool has_from;
    int locks[STUDIO_MAX_LOCKS];
    int lock_count;
} studio_fold_spec;

// orikin sequence --at T --json, as text (malloc'd; *size set): the same fields and values.
char *studio_json_at_text(double t, int fold, double drive_rad, const double *angles_rad, int edge_count,
                          double residual, const ori_v3 *positions, int vertex_count, size_t *size);
// A state of a computed fold (GET /api/fold/frame): frame, drive_deg, fold_angles_deg,
// residual, vertices_coords.
char *studio_json_frame_text(int frame, double drive_rad, const double *angles_rad, int edge_count, double residual,
                             const ori_v3 *positions, int vertex_count, size_t *size);
// orikin dof --json: the shared report (cli_dof_json; the info, tree and axiom answers call
// their cli/report/ builders directly).
static inline json_t *studio_json_dof(const char *file, int frame, const ori_dof_result *r, int loops)
{
    return cli_dof_json(file, frame, r, loops);
}

// A state as a binary body (little-endian float64): t, fold, drive_deg, residual, V, E, 0, 0,
// then 3V vertex coordinates and E fold angles in degrees. malloc'd; *size set.
char *studio_state_binary(double t, int fold, double drive_rad, double residual, const ori_v3 *positions, int V,
                          const double *angles_rad, int E, size_t *size);

#endif
