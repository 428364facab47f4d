// Fabrication tolerance (include/orikin/fab.h): the nominal fold, then seeded perturbed copies
// of the pattern folded the same way, each final pose compared with the nominal one.
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/fab.h>

#include "../core/core_internal.h"

struct ori_tolerance {
    ori_tolerance_sample *samples;
    int count, failed, contacts;
    double nominal_current;
};

ori_tolerance_def ori_default_tolerance_def(void)
{
    ori_tolerance_def d;
    memset(&d, 0, sizeof d);
    d.samples = 100;
    d.seed = 1;
    d.threads = 1;
    d.internal_value = 1;
    return d;
}

void ori_tolerance_destroy(ori_tolerance *t)
{
    if (!t) return;
    ori__free(t->samples);
    ori__free(t);
}

int ori_tolerance_sample_count(const ori_tolerance *t) { ORI_ASSERT(t); return t->count; }
int ori_tolerance_failed_count(const ori_tolerance *t) { ORI_ASSERT(t); return t->failed; }
int ori_tolerance_contact_count(const ori_tolerance *t) { ORI_ASSERT(t); return t->contacts; }
double ori_tolerance_nominal_current(const ori_tolerance *t) { ORI_ASSERT(t); return t->nominal_current; }

ori_tolerance_sample ori_tolerance_sample_at(const ori_tolerance *t, int i)
{
    ORI_ASSERT(t && i >= 0 && i < t->count);
    return t->samples[i];
}

double ori_tolerance_sample_metric(const ori_tolerance_sample *s, ori_tolerance_metric m)
{
    switch (m) {
    case ORI_TOLERANCE_METRIC_POSITION: return s->position_error;
    case ORI_TOLERANCE_METRIC_END_EFFECTOR: return s->end_effector_error;
    case ORI_TOLERANCE_METRIC_NORMAL: return s->normal_error_rad;
    case ORI_TOLERANCE_METRIC_ANGLE: return s->angle_error_rad;
    case ORI_TOLERANCE_METRIC_GAP: return s->gap;
    case ORI_TOLERANCE_METRIC_CURRENT: return s->current_a;
    default: return 0.0;
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double percentile(const double *v, int n, double p)
{
    double r = p * (n - 1);
    int k = (int)floor(r);
    if (k >= n - 1) return v[n - 1];
    return v[k] + (r - k) * (v[k + 1] - v[k]);
}

ori_tolerance_stats ori_tolerance_stats_of(const ori_tolerance *t, ori_tolerance_metric m)
{
    ORI_ASSERT(t);
    ori_tolerance_stats s;
    memset(&s, 0, sizeof s);
    double *v = ori__alloc(sizeof(double) * (size_t)(t->count ? t->count : 1));
    int n = 0;
    for (int i = 0; i < t->count; ++i)
        if (t->samples[i].folded) v[n++] = ori_tolerance_sample_metric(&t->samples[i], m);
    s.count = n;
    if (n > 0) {
        double sum = 0.0;
        for (int i = 0; i < n; ++i) sum += v[i];
        s.mean = sum / n;
        double ss = 0.0;
        for (int i = 0; i < n; ++i) ss += (v[i] - s.mean) * (v[i] - s.mean);
        s.sd = n > 1 ? sqrt(ss / (n - 1)) : 0.0;
        qsort(v, (size_t)n, sizeof *v, cmp_double);
        s.min = v[0];
        s.max = v[n - 1];
        s.p50 = percentile(v, n, 0.50);
        s.p90 = percentile(v, n, 0.90);
        s.p95 = percentile(v, n, 0.95);
        s.p99 = percentile(v, n, 0.99);
    }
    ori__free(v);
    return s;
}

// --- random numbers: splitmix64 (Steele, Lea, Flood 2014), one stream per sample ------------

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// Uniform in (0, 1]: 53 random bits.
static double uniform(uint64_t *state) { return ((double)(splitmix64(state) >> 11) + 1.0) * 0x1.0p-53; }

// Two independent standard normal deviates (Box–Muller).
static void normal2(uint64_t *state, double *a, double *b)
{
    double r = sqrt(-2.0 * log(uniform(state))), th = 2.0 * ORI_PI * uniform(state);
    *a = r * cos(th);
    *b = r * sin(th);
}

// --- one fold ----------------------------------------------------------------------------

typedef struct pose_state {
    ori_v3 *vertices;
    ori_v3 *normals;
    double *angles;
    bool has_ee;
    ori_v3 ee;
    double current_a;  // with a design: the sizing's current
    ori_design *design; // this worker's copy of the design (hinge widths set per sample), or NULL
} pose_state;

typedef struct job {
    const ori_tolerance_def *def;
    ori_motion_def motion;
    const ori_pattern *pattern;
    pose_state nominal;
    int *pairs; // contact pairs, 2 per pair
    int pair_count;
    ori_hinge *hinges; // the nominal hinges (edge_count), with has_hinge
    bool *has_hinge;
    ori_tolerance_sample *out;
    atomic_int next, done;
    atomic_bool cancel;
} job;

// Fold pattern p with the job's motion into st (allocated by the caller); false when it does
// not build or fold validly. *error (may be NULL) receives the failure.
static bool fold_one(const job *J, ori_pattern *p, pose_state *st, ori_error *error, ori_motion_verdict *verdict,
                     char *reason, size_t reason_size)
{
    ori_build_def bd = ori_default_build_def();
    if (!ori_pattern_is_built(p) && ori_pattern_build(p, &bd, error) != ORI_OK) return false;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, error) != ORI_OK) return false;
    ori_motion *mo = NULL;
    bool ok = ori_motion_solve(m, &J->motion, &mo, error) == ORI_OK;
    if (ok) {
        ori_motion_verdict v = ori_motion_verdict_of(mo);
        if (verdict) *verdict = v;
        if (reason && ori_motion_reason(mo)) ori__strlcpy(reason, ori_motion_reason(mo), reason_size);
        ok = v == ORI_MOTION_VALID && ori_motion_frame_count(mo) > 0;
    }
    if (ok) {
        int last = ori_motion_frame_count(mo) - 1;
        int nf = ori_pattern_face_count(p), ne = ori_pattern_edge_count(p);
        ori_motion_frame_vertices(mo, last, st->vertices);
        ori_rigid *poses = ori__alloc(sizeof(ori_rigid) * (size_t)nf);
        ori_motion_frame_face_poses(mo, last, poses);
        for (int f = 0; f < nf; ++f)
            st->normals[f] = ori_v3_make(poses[f].r.m[0][2], poses[f].r.m[1][2], poses[f].r.m[2][2]);
        ori__free(poses);
        memcpy(st->angles, ori_motion_frame_angles(mo, last), sizeof(double) * (size_t)ne);
        ori_v3 b;
        st->has_ee = ori_motion_frame_end_effector(mo, last, &st->ee, &b);
        if (st->design) {
            ori_sizing_def sd = ori_default_sizing_def();
            sd.design = st->design;
            sd.mechanism = m;
            sd.motion = mo;
            sd.driven_edge = J->motion.driven_edge;
            ori_sizing *z = NULL;
            ok = ori_sizing_solve(&sd, &z, error) == ORI_OK;
            st->current_a = ok ? ori_sizing_summary_of(z).current_needed_a : 0.0;
            ori_sizing_destroy(z);
        }
    }
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    return ok;
}

static void pose_alloc(pose_state *st, const ori_pattern *p)
{
    st->vertices = ori__alloc(sizeof(ori_v3) * (size_t)ori_pattern_vertex_count(p));
    st->normals = ori__alloc(sizeof(ori_v3) * (size_t)(ori_pattern_face_count(p) + 1));
    st->angles = ori__alloc(sizeof(double) * (size_t)(ori_pattern_edge_count(p) + 1));
    st->has_ee = false;
    st->current_a = 0.0;
    st->design = NULL;
}

static void pose_free(pose_state *st)
{
    ori__free(st->vertices);
    ori__free(st->normals);
    ori__free(st->angles);
    ori_design_destroy(st->design);
}

static void run_sample(job *J, int k, pose_state *st)
{
    const ori_tolerance_def *d = J->def;
    ori_tolerance_sample *s = &J->out[k];
    memset(s, 0, sizeof *s);
    ori_pattern *p = ori_pattern_clone(J->pattern);
    uint64_t state = d->seed ^ (0xd1b54a32d192ed03ULL * (uint64_t)(k + 1));
    splitmix64(&state);
    int nv = ori_pattern_vertex_count(p);
    for (int v = 0; v < nv; ++v) {
        double a, b;
        normal2(&state, &a, &b);
        ori_v3 q = ori_pattern_vertex(J->pattern, v);
        ori_pattern_set_vertex(p, v, ori_v3_make(q.x + d->vertex_sigma * a, q.y + d->vertex_sigma * b, 0.0));
    }
    if (d->vertex_sigma == 0.0) {
        // unchanged: keep the built topology (set_vertex invalidated it)
        ori_pattern_destroy(p);
        p = ori_pattern_clone(J->pattern);
    }
    bool widths_ok = true;
    for (int e = 0; st->design && e < ori_pattern_edge_count(p); ++e) {
        if (!J->has_hinge[e]) continue;
        double a, b;
        normal2(&state, &a, &b);
        ori_hinge h = J->hinges[e];
        h.width_m *= 1.0 + d->width_sigma_rel * a;
        if (h.has_wire && J->hinges[e].wire.width_m == J->hinges[e].width_m) h.wire.width_m = h.width_m; // the default conductor
        if (!(h.width_m > 0.0) || ori_design_set_hinge(st->design, e, &h, NULL) != ORI_OK) widths_ok = false;
    }
    s->folded = widths_ok && fold_one(J, p, st, NULL, NULL, NULL, 0);
    if (s->folded) {
        const pose_state *n = &J->nominal;
        for (int v = 0; v < nv; ++v) s->position_error = fmax(s->position_error, ori_v3_norm(ori_v3_sub(st->vertices[v], n->vertices[v])));
        for (int f = 0; f < ori_pattern_face_count(p); ++f)
            s->normal_error_rad = fmax(s->normal_error_rad, ori_angle_between_v3(st->normals[f], n->normals[f]));
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) s->angle_error_rad = fmax(s->angle_error_rad, fabs(st->angles[e] - n->angles[e]));
        if (st->has_ee && n->has_ee) s->end_effector_error = ori_v3_norm(ori_v3_sub(st->ee, n->ee));
        for (int i = 0; i < J->pair_count; ++i)
            s->gap = fmax(s->gap, ori_v3_norm(ori_v3_sub(st->vertices[J->pairs[2 * i]], st->vertices[J->pairs[2 * i + 1]])));
        s->current_a = st->current_a;
    }
    ori_pattern_destroy(p);
}

typedef struct worker_arg {
    job *J;
    pose_state st;
} worker_arg;

static void *worker(void *arg)
{
    worker_arg *w = arg;
    job *J = w->J;
    for (;;) {
        if (atomic_load(&J->cancel)) break;
        int k = atomic_fetch_add(&J->next, 1);
        if (k >= J->def->samples) break;
        run_sample(J, k, &w->st);
        atomic_fetch_add(&J->done, 1);
    }
    return NULL;
}

// A worker's design: created here, in the calling thread (the design reads the FOLD document).
static ori_status make_design(const ori_tolerance_def *d, pose_state *st, ori_error *error)
{
    if (!d->design) return ORI_OK;
    ori_design_def dd = *d->design;
    dd.pattern = d->pattern;
    return ori_design_create(&dd, &st->design, error);
}

ori_status ori_tolerance_run(const ori_tolerance_def *d, ori_tolerance **out, ori_error *error)
{
    ORI_ASSERT(d && out && d->internal_value == 1);
    *out = NULL;
    if (!d->pattern || !ori_pattern_is_built(d->pattern) || !d->motion)
        return ori__fail(error, ORI_ERR_ARGUMENT, "tolerance: a built pattern and a fold are needed");
    if (!(d->vertex_sigma >= 0.0) || !isfinite(d->vertex_sigma))
        return ori__fail_at(error, ORI_ERR_RANGE, "vertex_sigma", ORI_NULL_INDEX, "the vertex sigma must be a finite length ≥ 0");
    if (!(d->width_sigma_rel >= 0.0) || !isfinite(d->width_sigma_rel))
        return ori__fail_at(error, ORI_ERR_RANGE, "width_sigma_rel", ORI_NULL_INDEX, "the width sigma must be a finite number ≥ 0");
    if (d->samples < 1 || d->samples > ORI_TOLERANCE_MAX_SAMPLES)
        return ori__fail_at(error, ORI_ERR_RANGE, "samples", ORI_NULL_INDEX, "samples must be 1 to %d", ORI_TOLERANCE_MAX_SAMPLES);
    job J;
    memset(&J, 0, sizeof J);
    J.def = d;
    J.motion = *d->motion;
    J.motion.last_frame_only = !d->design; // the sizing follows every frame
    J.motion.progress = NULL;
    J.pattern = d->pattern;
    pose_alloc(&J.nominal, d->pattern);
    ori_status st0 = make_design(d, &J.nominal, error);
    if (st0 != ORI_OK) {
        pose_free(&J.nominal);
        return st0;
    }
    ori_pattern *nom = ori_pattern_clone(d->pattern);
    ori_motion_verdict verdict = ORI_MOTION_VALID;
    char reason[256] = "";
    ori_error err;
    ori_error_clear(&err);
    bool ok = fold_one(&J, nom, &J.nominal, &err, &verdict, reason, sizeof reason);
    ori_pattern_destroy(nom);
    if (!ok) {
        pose_free(&J.nominal);
        if (err.status != ORI_OK) {
            if (error) *error = err;
            return err.status;
        }
        return ori__fail(error, ORI_ERR_ARGUMENT, "the nominal fold is %s: %s", ori_motion_verdict_name(verdict), reason);
    }
    // Contacts: vertex pairs that meet in the nominal final state but not in the flat sheet.
    int nv = ori_pattern_vertex_count(d->pattern), cap = 0;
    double tol = ORI_TOL_FAB_CONTACT_REL * ori_pattern_diagonal(d->pattern);
    for (int i = 0; i < nv; ++i)
        for (int j = i + 1; j < nv; ++j)
            if (ori_v3_norm(ori_v3_sub(J.nominal.vertices[i], J.nominal.vertices[j])) < tol) {
                ori__grow((void **)&J.pairs, &cap, 2 * J.pair_count + 2, sizeof(int));
                J.pairs[2 * J.pair_count] = i;
                J.pairs[2 * J.pair_count + 1] = j;
                J.pair_count++;
            }
    int ne = ori_pattern_edge_count(d->pattern);
    J.hinges = ori__calloc((size_t)(ne ? ne : 1), sizeof *J.hinges);
    J.has_hinge = ori__calloc((size_t)(ne ? ne : 1), sizeof *J.has_hinge);
    for (int e = 0; J.nominal.design && e < ne; ++e) J.has_hinge[e] = ori_design_hinge(J.nominal.design, e, &J.hinges[e]);
    J.out = ori__calloc((size_t)d->samples, sizeof *J.out);
    atomic_init(&J.next, 0);
    atomic_init(&J.done, 0);
    atomic_init(&J.cancel, false);
    int extra = d->threads > 1 ? d->threads - 1 : 0;
    if (extra > d->samples - 1) extra = d->samples - 1;
    pthread_t *tids = ori__alloc(sizeof(pthread_t) * (size_t)(extra ? extra : 1));
    worker_arg *args = ori__calloc((size_t)(extra ? extra : 1), sizeof *args);
    int started = 0;
    ori_status design_status = ORI_OK;
    for (int i = 0; i < extra && design_status == ORI_OK; ++i) {
        args[i].J = &J;
        pose_alloc(&args[i].st, d->pattern);
        if ((design_status = make_design(d, &args[i].st, error)) != ORI_OK) break;
        if (pthread_create(&tids[i], NULL, worker, &args[i]) == 0) started++;
    }
    // the calling thread works too, reporting progress between its samples (with the nominal's design)
    pose_state st = J.nominal;
    J.nominal.design = NULL;
    double nominal_current = st.current_a;
    pose_alloc(&J.nominal, d->pattern); // (kept for the comparisons: copy the nominal pose back)
    memcpy(J.nominal.vertices, st.vertices, sizeof(ori_v3) * (size_t)ori_pattern_vertex_count(d->pattern));
    memcpy(J.nominal.normals, st.normals, sizeof(ori_v3) * (size_t)ori_pattern_face_count(d->pattern));
    memcpy(J.nominal.angles, st.angles, sizeof(double) * (size_t)ne);
    J.nominal.has_ee = st.has_ee;
    J.nominal.ee = st.ee;
    J.nominal.current_a = nominal_current;
    bool cancelled = design_status != ORI_OK;
    if (cancelled) atomic_store(&J.cancel, true);
    for (; !cancelled;) {
        int k = atomic_fetch_add(&J.next, 1);
        if (k >= d->samples) break;
        run_sample(&J, k, &st);
        int done = atomic_fetch_add(&J.done, 1) + 1;
        if (d->progress && !d->progress((double)done / d->samples, d->progress_user)) {
            cancelled = true;
            atomic_store(&J.cancel, true);
            break;
        }
    }
    pose_free(&st);
    for (int i = 0; i < started; ++i) pthread_join(tids[i], NULL);
    for (int i = 0; i < extra; ++i)
        if (args[i].J) pose_free(&args[i].st);
    ori__free(args);
    ori__free(tids);
    pose_free(&J.nominal);
    ori__free(J.pairs);
    ori__free(J.hinges);
    ori__free(J.has_hinge);
    if (cancelled) {
        ori__free(J.out);
        return design_status != ORI_OK ? design_status : ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
    if (d->progress) d->progress(1.0, d->progress_user);
    ori_tolerance *t = ori__calloc(1, sizeof *t);
    t->samples = J.out;
    t->count = d->samples;
    t->contacts = J.pair_count;
    t->nominal_current = nominal_current;
    for (int i = 0; i < t->count; ++i) t->failed += !t->samples[i].folded;
    *out = t;
    return ORI_OK;
}
