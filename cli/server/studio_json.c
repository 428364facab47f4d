// The API's JSON: field for field what the CLI prints with --json (tests/test_server.c runs
// both and compares them), so that a script and the page read the same answers.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

static json_t *v3_json(ori_v3 v)
{
    return json_pack("[fff]", v.x, v.y, v.z);
}

static json_t *ints_json(const int *e, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i) json_array_append_new(a, json_integer(e[i]));
    return a;
}

static json_t *degrees_json(const double *a, int n)
{
    json_t *arr = json_array();
    for (int e = 0; e < n; ++e) json_array_append_new(arr, json_real(ori_rad_to_deg_output(a[e])));
    return arr;
}

// --- orikin fold --json --------------------------------------------------------------------

static const char *solver_name(ori_motion_stats st)
{
    return st.analytic ? "analytic" : st.sweep ? "numeric-sweep" : st.sparse ? "numeric-sparse" : "numeric-dense";
}

static json_t *chain_json(const int *edges, const ori_v3 *q, const ori_v3 *w, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i)
        json_array_append_new(a, json_pack("{s:i,s:o,s:o}", "edge", edges[i], "q", v3_json(q[i]), "omega", v3_json(w[i])));
    return a;
}

// Interior vertices of even degree that miss Kawasaki by a little (rounded coordinates).
static int near_kawasaki_misses(const ori_pattern *p, double *worst)
{
    int n = 0;
    *worst = 0.0;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        ori_vertex_report r;
        ori_flat_check_vertex(p, v, &r);
        if (r.degree % 2 || r.kawasaki || fabs(r.kawasaki_rad) > STUDIO_HINT_NEAR_KAWASAKI_RAD) continue;
        n++;
        *worst = fmax(*worst, fabs(r.kawasaki_rad));
    }
    return n;
}

static json_t *rounding_hint(const ori_pattern *flat, const ori_motion *mo)
{
    if (ori_motion_verdict_of(mo) != ORI_MOTION_NOT_RIGIDLY_FOLDABLE) return json_null();
    double worst;
    int n = near_kawasaki_misses(flat, &worst);
    if (n == 0) return json_null();
    char buf[512];
    snprintf(buf, sizeof buf,
             "%d interior vertices miss Kawasaki by up to %.2g rad (rounded coordinates?): rigid folding is "
             "exact, and such a sheet is rigid even where its exact design folds; orikin check lists them",
             n, worst);
    return json_string(buf);
}

json_t *studio_json_fold(const char *file, const studio_fold_spec *a, const ori_pattern *flat,
                         const ori_mechanism *m, const ori_motion *mo, const cli_collision *col, const char *lock_hint)
{
    int E = ori_mechanism_edge_count(m);
    ori_motion_verdict v = ori_motion_verdict_of(mo);
    ori_motion_stats st = ori_motion_stats_of(mo);
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    char hit[256];
    cli_collision_describe(col, false, hit, sizeof hit);
    bool collides = cli_collides(col);
    json_object_set_new(out, "valid", json_boolean(v == ORI_MOTION_VALID && !collides));
    json_object_set_new(out, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(v)));
    const char *why = collides ? hit : ori_motion_reason(mo);
    json_object_set_new(out, "reason", why ? json_string(why) : json_null());
    json_object_set_new(out, "collision", cli_collision_json(col, false));
    json_t *hint = rounding_hint(flat, mo);
    if (json_is_null(hint) && lock_hint && lock_hint[0]) { // underdetermined: a lock set (as orikin fold)
        json_decref(hint);
        hint = json_string(lock_hint);
    }
    json_object_set_new(out, "hint", hint);
    json_object_set_new(out, "rigidly_foldable", json_boolean(v != ORI_MOTION_NOT_RIGIDLY_FOLDABLE));
    json_object_set_new(out, "dof", cli_motion_dof_json(mo));
    json_object_set_new(out, "grubler", json_integer(ori_mechanism_grubler(m)));
    json_object_set_new(out, "solver", json_string(solver_name(st)));
    json_object_set_new(out, "fixed_face", json_integer(a->fix));
    json_object_set_new(out, "drive", json_integer(a->drive));
    json_object_set_new(out, "to_deg", json_real(a->to_deg));
    json_object_set_new(out, "step_deg", json_real(a->step_deg));
    json_object_set_new(out, "locked", ints_json(a->locks, a->lock_count));
    ori_vertex_split sp;
    if (ori_motion_split(mo, &sp)) {
        json_object_set_new(out, "frame_a", ints_json(sp.frame_a, 2));
        json_object_set_new(out, "frame_b", ints_json(sp.frame_b, sp.frame_b_count));
        json_object_set_new(out, "surrounding", ints_json(sp.surrounding, sp.surrounding_count));
        json_t *s = json_object();
        json_object_set_new(s, "vertex", json_integer(sp.vertex));
        json_object_set_new(s, "end_effector_vertex", json_integer(sp.end_effector_vertex));
        json_object_set_new(s, "origin_a", v3_json(sp.origin_a));
        json_object_set_new(s, "origin_b", v3_json(sp.origin_b));
        json_object_set_new(s, "d", v3_json(sp.d));
        json_object_set_new(s, "chain_a", chain_json(sp.frame_a, sp.q_a, sp.omega_a, 2));
        json_object_set_new(s, "chain_b", chain_json(sp.frame_b, sp.q_b, sp.omega_b, sp.frame_b_count));
        json_object_set_new(out, "split", s);
    }
    json_t *off = json_array();
    for (int i = 0; i < ori_motion_violation_count(mo); ++i) {
        ori_crease_violation fv = ori_motion_violation(mo, i);
        char as[2] = {ori_assignment_to_char(fv.assignment), '\0'};
        json_array_append_new(off, json_pack("{s:i,s:s,s:f,s:f}", "edge", fv.edge, "assignment", as, "angle_deg",
                                             ori_rad_to_deg_output(fv.angle_rad), "at_drive_deg",
                                             ori_rad_to_deg_output(fv.drive_rad)));
    }
    json_object_set_new(out, "offending_edges", off);
    json_object_set_new(out, "blocked", cli_motion_block_json(mo));
    json_object_set_new(out, "partial", json_boolean(cli_motion_partial(mo, col)));
    json_t *frames = json_array();
    double *alt = malloc(sizeof(double) * (size_t)(E + 1));
    for (int f = 0; f < cli_collide_frames(col, ori_motion_frame_count(mo)); ++f) {
        json_t *fr = json_object();
        json_object_set_new(fr, "drive_deg", json_real(ori_rad_to_deg_output(ori_motion_frame_drive(mo, f))));
        json_object_set_new(fr, "fold_angles_deg", degrees_json(ori_motion_frame_angles(mo, f), E));
        json_object_set_new(fr, "residual", json_real(ori_motion_frame_residual(mo, f)));
        if (ori_motion_frame_other_branch(mo, f, alt)) json_object_set_new(fr, "other_branch_deg", degrees_json(alt, E));
        ori_v3 ea, eb;
        if (ori_motion_frame_end_effector(mo, f, &ea, &eb))
            json_object_set_new(fr, "end_effector", json_pack("{s:o,s:o}", "frame_a", v3_json(ea), "frame_b", v3_json(eb)));
        json_array_append_new(frames, fr);
    }
    free(alt);
    json_object_set_new(out, "frames", frames);
    json_object_set_new(out, "stats",
                        json_pack("{s:i,s:i,s:i,s:i,s:i,s:f}", "steps", st.steps, "rejected_steps", st.rejected_steps,
                                  "newton_iterations", st.newton_iterations, "sweep_iterations", st.sweep_iterations,
                                  "factorizations", st.factorizations, "max_residual", st.max_residual));
    return out;
}

// --- orikin sequence --json and --at T --json ------------------------------------------------

static json_t *sequence_fold_json(const ori_sequence_fold *f, int i)
{
    json_t *o = json_object();
    json_object_set_new(o, "fold", json_integer(i + 1));
    json_object_set_new(o, "name", f->name[0] ? json_string(f->name) : json_null());
    json_object_set_new(o, "fix", json_integer(f->fixed_face));
    json_object_set_new(o, "drive", f->targets ? json_null() : json_integer(f->driven_edge));
    if (f->targets) json_object_set_new(o, "percent", json_real(100.0 * f->fraction)); // a fold toward the targets
    json_object_set_new(o, "lock", ints_json(f->locked, f->locked_count));
    json_object_set_new(o, "from_deg", f->has_from ? json_real(ori_rad_to_deg_output(f->from_rad)) : json_null());
    json_object_set_new(o, "to_deg", json_real(ori_rad_to_deg_output(f->to_rad)));
    json_object_set_new(o, "step_deg", json_real(ori_rad_to_deg_output(f->step_rad)));
    return o;
}

json_t *studio_json_record(const char *sequence, const char *pattern, const ori_sequence *s, const ori_record *r,
                           int E, const cli_collision *col)
{
    json_t *o = json_object();
    char hit[256];
    cli_collision_describe(col, true, hit, sizeof hit);
    bool collides = cli_collides(col);
    json_object_set_new(o, "sequence", json_string(sequence));
    json_object_set_new(o, "pattern", json_string(pattern));
    const char *why = collides ? hit : ori_record_reason(r);
    json_object_set_new(o, "valid", json_boolean(ori_record_verdict(r) == ORI_MOTION_VALID && !collides));
    json_object_set_new(o, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(ori_record_verdict(r))));
    json_object_set_new(o, "reason", why ? json_string(why) : json_null());
    json_object_set_new(o, "collision", cli_collision_json(col, true));
    int failed = ori_record_failed_fold(r);
    json_object_set_new(o, "failed_fold", failed >= 0 ? json_integer(failed + 1) : json_null());
    json_object_set_new(o, "duration", json_integer(ori_record_completed_folds(r)));
    json_object_set_new(o, "partial_frames", json_integer(ori_record_partial_frames(r)));
    json_t *folds = json_array();
    for (int i = 0; i < ori_sequence_fold_count(s); ++i) {
        ori_sequence_fold f = ori_sequence_fold_at(s, i);
        json_array_append_new(folds, sequence_fold_json(&f, i));
    }
    json_object_set_new(o, "folds", folds);
    json_t *frames = json_array();
    for (int f = 0; f < cli_collide_frames(col, ori_record_frame_count(r)); ++f) {
        json_t *fr = json_object();
        json_object_set_new(fr, "t", json_real(ori_record_frame_time(r, f)));
        json_object_set_new(fr, "fold", json_integer(ori_record_frame_fold(r, f) + 1));
        bool tg = ori_sequence_fold_at(s, ori_record_frame_fold(r, f)).targets; // progress, not an angle
        json_object_set_new(fr, "drive_deg", tg ? json_null() : json_real(ori_rad_to_deg_output(ori_record_frame_drive(r, f))));
        json_object_set_new(fr, "fold_angles_deg", degrees_json(ori_record_frame_angles(r, f), E));
        json_object_set_new(fr, "residual", json_real(ori_record_frame_residual(r, f)));
        json_array_append_new(frames, fr);
    }
    json_object_set_new(o, "frames", frames);
    return o;
}

// A growing text buffer for the state answers, written directly: a 100 × 100 Miura-ori state
// has 50,000 numbers, which a JSON tree and its normalisation take ten times longer to write.
typedef struct text_buf {
    char *p;
    size_t n, cap;
} text_buf;

static void tb_reserve(text_buf *b, size_t more)
{
    if (b->n + more + 1 <= b->cap) return;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + more + 1) cap *= 2;
    b->p = realloc(b->p, cap);
    b->cap = cap;
}

static void tb_str(text_buf *b, const char *s)
{
    size_t k = strlen(s);
    tb_reserve(b, k);
    memcpy(b->p + b->n, s, k + 1);
    b->n += k;
}

// A number that reads back exactly: integers as integers (0, 90, 180 are common), anything
// else with 17 significant digits (always enough for a double; the CLI prints the shortest
// such form, which parses to the same double).
static void tb_num(text_buf *b, double x)
{
    tb_reserve(b, 32);
    int k;
    if (x == floor(x) && fabs(x) < 1e15) k = snprintf(b->p + b->n, 32, "%.0f", x == 0.0 ? 0.0 : x);
    else k = snprintf(b->p + b->n, 32, "%.17g", x);
    b->n += (size_t)k;
}

static void tb_degrees(text_buf *b, const double *a, int n)
{
    tb_str(b, "[");
    for (int e = 0; e < n; ++e) {
        if (e) tb_str(b, ",");
        tb_num(b, ori_rad_to_deg_output(a[e]));
    }
    tb_str(b, "]");
}

static void tb_coords(text_buf *b, const ori_v3 *pos, int V)
{
    tb_str(b, "[");
    for (int v = 0; v < V; ++v) {
        tb_str(b, v ? ",[" : "[");
        tb_num(b, pos[v].x);
        tb_str(b, ",");
        tb_num(b, pos[v].y);
        tb_str(b, ",");
        tb_num(b, pos[v].z);
        tb_str(b, "]");
    }
    tb_str(b, "]");
}

char *studio_json_at_text(double t, int fold, double drive_rad, const double *angles_rad, int E, double residual,
                          const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"t\":");
    tb_num(&b, t);
    tb_str(&b, ",\"fold\":");
    tb_num(&b, fold + 1);
    tb_str(&b, ",\"drive_deg\":");
    if (isnan(drive_rad)) tb_str(&b, "null"); // a fold toward the targets has no drive angle
    else tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

char *studio_json_frame_text(int frame, double drive_rad, const double *angles_rad, int E, double residual,
                             const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"frame\":");
    tb_num(&b, frame);
    tb_str(&b, ",\"drive_deg\":");
    tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

// Little-endian float64 whatever the host.
static void put_f64(unsigned char *p, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    for (int i = 0; i < 8; ++i) p[i] = (unsigned char)(u >> (8 * i));
}

char *studio_state_binary(double t, int fold, double drive_rad, double residual, const ori_v3 *pos, int V,
                          const double *angles_rad, int E, size_t *size)
{
    size_t n = 8 + 3 * (size_t)V + (size_t)E;
    unsigned char *b = malloc(8 * n);
    double head[8] = {t, (double)(fold + 1), ori_rad_to_deg_output(drive_rad), residual, (double)V, (double)E, 0.0, 0.0};
    size_t k = 0;
    for (int i = 0; i < 8; ++i) put_f64(b + 8 * k++, head[i]);
    for (int v = 0; v < V; ++v) {
        put_f64(b + 8 * k++, pos[v].x);
        put_f64(b + 8 * k++, pos[v].y);
        put_f64(b + 8 * k++, pos[v].z);
    }
    for (int e = 0; e < E; ++e) put_f64(b + 8 * k++, ori_rad_to_deg_output(angles_rad[e]));
    *size = 8 * n;
    return (char *)b;
}

// --- orikin dof, tree, info, axiom --json ----------------------------------------------------

json_t *studio_json_dof(const char *file, int frame, const ori_dof_result *r, int loops)
{
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "frame", json_integer(frame));
    json_object_set_new(out, "grubler", json_integer(r->grubler));
    json_object_set_new(out, "unknowns", json_integer(r->unknowns));
    json_object_set_new(out, "equations", json_integer(r->equations));
    json_object_set_new(out, "rank", json_integer(r->rank));
    json_object_set_new(out, "dof", json_integer(r->dof));
    json_object_set_new(out, "generic_dof", r->generic_dof >= 0 ? json_integer(r->generic_dof) : json_null());
    json_object_set_new(out, "singular", json_boolean(r->singular));
    json_object_set_new(out, "rigid", json_boolean(r->rigid));
    json_object_set_new(out, "undetermined", json_boolean(r->undetermined));
    json_object_set_new(out, "probe_solves", json_integer(r->probe_solves));
    json_object_set_new(out, "method", json_string(r->dense ? "dense-svd" : "sparse-cholmod"));
    json_object_set_new(out, "sigma_max", json_real(r->sigma_max));
    json_object_set_new(out, "sigma_cut", json_real(r->sigma_cut));
    json_object_set_new(out, "loops", json_integer(loops));
    return out;
}

json_t *studio_json_tree(const char *file, const ori_pattern *p)
{
    int nodes = ori_pattern_tree_node_count(p), faces = ori_pattern_face_count(p);
    // children by parent in one pass (the CLI's double loop is quadratic)
    int *first = malloc(sizeof(int) * (size_t)(nodes + 1)), *next = malloc(sizeof(int) * (size_t)(nodes + 1));
    for (int i = 0; i < nodes; ++i) first[i] = next[i] = -1;
    for (int k = nodes - 1; k >= 0; --k) {
        int parent = ori_pattern_tree_node(p, k).parent;
        if (parent >= 0 && parent < nodes) {
            next[k] = first[parent];
            first[parent] = k;
        }
    }
    json_t *arr = json_array();
    for (int i = 0; i < nodes; ++i) {
        ori_tree_node n = ori_pattern_tree_node(p, i);
        json_t *children = json_array();
        for (int k = first[i]; k >= 0; k = next[k]) json_array_append_new(children, json_string(ori_pattern_tree_node(p, k).name));
        int face = ori_pattern_find_face_by_name(p, n.name);
        json_t *o = json_object();
        json_object_set_new(o, "name", json_string(n.name));
        json_object_set_new(o, "parent", json_integer(n.parent));
        json_object_set_new(o, "children", children);
        json_object_set_new(o, "leaf", json_boolean(first[i] < 0));
        json_object_set_new(o, "face", face == ORI_NULL_INDEX ? json_null() : json_integer(face));
        json_array_append_new(arr, o);
    }
    free(first);
    free(next);
    json_t *elems = json_array();
    for (int f = 0; f < faces; ++f) {
        const char *name = ori_pattern_face_name(p, f);
        json_t *o = json_object();
        json_object_set_new(o, "face", json_integer(f));
        json_object_set_new(o, "name", name ? json_string(name) : json_null());
        json_array_append_new(elems, o);
    }
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "nodes", arr);
    json_object_set_new(out, "folding_elements", elems);
    return out;
}

json_t *studio_json_info(const char *file, int frame, int frames, const ori_pattern *p)
{
    json_t *by = json_object();
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) {
        char key[2] = {ori_assignment_to_char((ori_assignment)a), '\0'};
        json_object_set_new(by, key, json_integer(ori_pattern_count_assignment(p, (ori_assignment)a)));
    }
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "frame", json_integer(frame));
    json_object_set_new(out, "frames", json_integer(frames));
    json_object_set_new(out, "vertices", json_integer(ori_pattern_vertex_count(p)));
    json_object_set_new(out, "edges", json_integer(ori_pattern_edge_count(p)));
    json_object_set_new(out, "edges_by_assignment", by);
    json_object_set_new(out, "faces", json_integer(ori_pattern_face_count(p)));
    json_object_set_new(out, "interior_vertices", json_integer(ori_pattern_interior_vertex_count(p)));
    json_object_set_new(out, "dimension", json_integer(ori_pattern_is_3d(p) ? 3 : 2));
    json_object_set_new(out, "folded_form", json_boolean(ori_pattern_is_folded_form(p)));
    return out;
}

json_t *studio_json_axiom(int axiom, const ori_line_set *set)
{
    json_t *lines = json_array();
    for (int k = 0; k < set->count; ++k) {
        ori_line l = set->lines[k];
        json_array_append_new(lines, json_pack("{s:[ff],s:[ff]}", "point", l.point.x, l.point.y, "dir", l.dir.x, l.dir.y));
    }
    return json_pack("{s:i,s:o}", "axiom", axiom, "lines", lines);
}

// --- orikin collide --json ---------------------------------------------------------------------

static json_t *pairs_json(const ori_collider *c, bool colliding)
{
    json_t *arr = json_array();
    for (int i = 0; i < ori_collider_contact_count(c); ++i) {
        ori_contact k = ori_collider_contact(c, i);
        bool take = colliding ? k.collides : k.kind == ORI_CONTACT_TOUCHING;
        if (take) json_array_append_new(arr, json_pack("[ii]", k.face_a, k.face_b));
    }
    return arr;
}

static const char *contact_kind_name(ori_contact_kind k)
{
    return k == ORI_CONTACT_PENETRATING ? "penetrating" : k == ORI_CONTACT_TOUCHING ? "touching" : "near";
}

json_t *studio_json_collide(const char *file, int frame, bool posed, const ori_collider *c, const ori_collision_result *r,
                            double clearance, const ori_cloud_result *cr, double cloud_spacing, double cloud_distance)
{
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(file));
    json_object_set_new(o, "frame", frame >= 0 ? json_integer(frame) : json_null());
    json_object_set_new(o, "posed", json_boolean(posed));
    json_object_set_new(o, "faces", json_integer(ori_collider_face_count(c)));
    json_object_set_new(o, "collides", json_boolean(r->collides));
    json_object_set_new(o, "pairs", pairs_json(c, true));
    json_object_set_new(o, "touching", pairs_json(c, false));
    json_object_set_new(o, "min_clearance", isfinite(r->min_clearance) ? json_real(r->min_clearance) : json_null());
    json_object_set_new(o, "witness", r->has_witness ? v3_json(r->witness) : json_null());
    json_object_set_new(o, "clearance_faces", r->clearance_faces[0] >= 0
                                                  ? json_pack("[ii]", r->clearance_faces[0], r->clearance_faces[1])
                                                  : json_null());
    json_object_set_new(o, "clearance", json_real(clearance));
    json_object_set_new(o, "tolerance", json_real(r->tolerance));
    json_t *contacts = json_array();
    for (int i = 0; i < ori_collider_contact_count(c); ++i) {
        ori_contact k = ori_collider_contact(c, i);
        json_t *x = json_object();
        json_object_set_new(x, "faces", json_pack("[ii]", k.face_a, k.face_b));
        json_object_set_new(x, "kind", json_string(contact_kind_name(k.kind)));
        json_object_set_new(x, "adjacent", json_boolean(k.adjacent));
        json_object_set_new(x, "stacked", json_boolean(k.stacked));
        json_object_set_new(x, "point", v3_json(k.point));
        if (k.kind == ORI_CONTACT_NEAR) json_object_set_new(x, "distance", json_real(k.distance));
        json_array_append_new(contacts, x);
    }
    json_object_set_new(o, "contacts", contacts);
    json_object_set_new(o, "candidate_pairs", json_integer(r->candidate_pairs));
    if (cr) {
        json_t *cl = json_object();
        json_object_set_new(cl, "spacing", json_real(cloud_spacing));
        json_object_set_new(cl, "distance", json_real(cloud_distance));
        json_object_set_new(cl, "points", json_integer(cr->points));
        json_object_set_new(cl, "point_pairs", json_integer(cr->point_pairs));
        json_object_set_new(cl, "min_distance", isfinite(cr->min_distance) ? json_real(cr->min_distance) : json_null());
        json_t *fp = json_array();
        for (int i = 0; i < ori_collider_cloud_pair_count(c); ++i) {
            ori_cloud_pair p = ori_collider_cloud_pair(c, i);
            json_array_append_new(fp, json_pack("{s:[ii],s:I,s:f}", "faces", p.face_a, p.face_b, "point_pairs",
                                                (json_int_t)p.point_pairs, "distance", p.distance));
        }
        json_object_set_new(cl, "faces", fp);
        json_object_set_new(o, "cloud", cl);
    } else {
        json_object_set_new(o, "cloud", json_null());
    }
    return o;
}
