// libFuzzer target for the collision checker (collision.h, issue 27 item 6): fuzzed small patterns
// (fuzz_kin.h: a single vertex of degree 4–8 or a generated tessellation of at most 2 × 2 cells)
// folded along a fuzzed fold (coarse steps, ≥ 10°), then: ori_collider_create with a fuzzed
// clearance (hostile values too: 0, −0, negative, NaN, ±inf, huge, tiny), ori_collider_check at a
// few frames and at a hostile state (fold angles that need not close, vertices moved anywhere, a
// coordinate not finite), the cloud of proximity with fuzzed spacing and distance (hostile too,
// a small sample limit), and
// ori_collision_check_motion / _trajectory on the fold, _record on a one- or two-fold sequence and
// _multifold on a bounded target fold, with a fuzzed drive tolerance.
// Invariants: no crash, leak or sanitizer report; a refusal carries a message (and a bad
// clearance, spacing, distance or drive tolerance is refused with ORI_ERR_RANGE); the contact
// counts add up and are at most the face pairs; contacts are sorted, name faces a < b < face count,
// flag adjacency as ori_collider_adjacent says, NEAR only for faces sharing no vertex and only with
// a clearance, distances finite in [0, clearance); collides as the contacts say; the same input
// twice gives the same answer; at a smaller clearance the penetrating and touching pairs are the
// same, the NEAR pairs a subset (those nearer than it), the least clearance the same; brute force:
// the least clearance is at most any vertex–vertex distance of two faces sharing no vertex, and a
// pair with two vertices nearer than the clearance is reported, two triangles one of whose edges
// passes through the other well inside are reported penetrating; cloud pairs are sorted, share no
// vertex, lie within the distance and not below the exact clearance; a motion's first colliding
// frame has only clean frames before it (checked one by one), a clean motion only clean frames,
// and the trajectory view gives the same event as the direct call.
#include "fuzz_kin.h"
#include <float.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FC_MAX_FACES 40

// A hostile or ordinary length of scale L: 0, −0, negative, NaN, ±inf, huge, tiny, or in [0, L/2].
static double fc_length(fk_bytes *b, double L)
{
    switch (fk_u8(b) % 12) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return -fk_range(b, 0.0, 1.0) * L - 1e-300;
    case 3: return NAN;
    case 4: return INFINITY;
    case 5: return -INFINITY;
    case 6: return 1e300;
    case 7: return 1e-300;
    case 8: return DBL_MAX;
    default: return fk_range(b, 0.0, 0.5) * L;
    }
}

static void fc_refusal(ori_status st, const ori_error *err)
{
    if (st == ORI_OK) return;
    if (err->status != st || err->message[0] == '\0') abort(); // a refusal says why
}

typedef struct fc_pairs {
    int n;
    int a[FC_MAX_FACES * FC_MAX_FACES], b[FC_MAX_FACES * FC_MAX_FACES];
    ori_contact k[FC_MAX_FACES * FC_MAX_FACES];
} fc_pairs;

static bool fc_same_contact(const ori_contact *x, const ori_contact *y)
{
    return x->face_a == y->face_a && x->face_b == y->face_b && x->kind == y->kind && x->adjacent == y->adjacent &&
           x->stacked == y->stacked && x->collides == y->collides && x->distance == y->distance &&
           x->point.x == y->point.x && x->point.y == y->point.y && x->point.z == y->point.z;
}

// Face vertex lists of the pattern (at most 16 vertices a face).
typedef struct fc_faces {
    int n[FC_MAX_FACES];
    int v[FC_MAX_FACES][16];
} fc_faces;

// The invariants of one check whose result is r (clearance c) and contacts into out.
static void fc_check_result(const ori_collider *col, double c, const ori_collision_result *r, fc_pairs *out)
{
    int F = ori_collider_face_count(col);
    int n = ori_collider_contact_count(col);
    if (n != r->contact_count || r->contact_count != r->penetrating + r->touching + r->near) abort();
    if (r->penetrating < 0 || r->touching < 0 || r->near < 0) abort();
    if ((int64_t)n > (int64_t)F * (F - 1) / 2) abort();
    if (c == 0.0 && r->near != 0) abort();
    int pen = 0, tou = 0, nea = 0;
    bool any = false;
    out->n = n;
    for (int i = 0; i < n; ++i) {
        ori_contact k = ori_collider_contact(col, i);
        out->k[i] = k;
        if (!(k.face_a >= 0 && k.face_a < k.face_b && k.face_b < F)) abort();
        if (i > 0) {
            ori_contact prev = out->k[i - 1];
            if (prev.face_a > k.face_a || (prev.face_a == k.face_a && prev.face_b >= k.face_b)) abort(); // sorted, no repeats
        }
        if (k.adjacent != ori_collider_adjacent(col, k.face_a, k.face_b)) abort();
        if (!isfinite(k.distance) || k.distance < 0.0) abort();
        if (!isfinite(k.point.x) || !isfinite(k.point.y) || !isfinite(k.point.z)) abort();
        switch (k.kind) {
        case ORI_CONTACT_PENETRATING:
            pen++;
            if (!k.collides || k.distance != 0.0) abort();
            break;
        case ORI_CONTACT_TOUCHING:
            tou++;
            if (k.distance != 0.0 || k.collides != (!k.adjacent && c > 0.0)) abort();
            break;
        case ORI_CONTACT_NEAR:
            nea++;
            if (k.adjacent || !k.collides || !(c > 0.0) || !(k.distance < c)) abort();
            if (!(k.distance >= r->min_clearance)) abort();
            break;
        default: abort();
        }
        any = any || k.collides;
    }
    if (pen != r->penetrating || tou != r->touching || nea != r->near) abort();
    if (any != r->collides) abort();
    if (!(r->min_clearance >= 0.0)) abort(); // NaN or negative
    if (isfinite(r->min_clearance)) {
        int f = r->clearance_faces[0], g = r->clearance_faces[1];
        if (!(f >= 0 && f < F && g >= 0 && g < F && f != g)) abort();
        if (ori_collider_adjacent(col, f, g)) abort();
    } else if (r->min_clearance != INFINITY) {
        abort();
    }
    if (!isfinite(r->tolerance) || r->tolerance < 0.0) abort();
    if (r->candidate_pairs < 0 || r->distance_pairs < 0) abort();
}

// Brute force on the vertices: the least clearance is at most any vertex–vertex distance of
// two faces sharing no vertex; a pair with vertices nearer than the clearance is reported.
static void fc_brute(const ori_collider *col, const fc_faces *fv, const ori_v3 *pos, double c, double tol,
                     const ori_collision_result *r, const fc_pairs *got)
{
    int F = ori_collider_face_count(col);
    for (int f = 0; f < F; ++f)
        for (int g = f + 1; g < F; ++g) {
            if (ori_collider_adjacent(col, f, g)) continue;
            double d = INFINITY;
            for (int i = 0; i < fv->n[f]; ++i)
                for (int j = 0; j < fv->n[g]; ++j) d = fmin(d, ori_v3_norm(ori_v3_sub(pos[fv->v[f][i]], pos[fv->v[g][j]])));
            if (!(r->min_clearance <= d + tol)) {
                fprintf(stderr, "faces %d and %d: vertices %.17g apart, least clearance %.17g\n", f, g, d, r->min_clearance);
                abort();
            }
            if (d < c - tol) {
                bool found = false;
                for (int i = 0; i < got->n && !found; ++i) found = got->k[i].face_a == f && got->k[i].face_b == g;
                if (!found) {
                    fprintf(stderr, "faces %d and %d: vertices %.17g apart, clearance %.17g, not reported\n", f, g, d, c);
                    abort();
                }
            }
        }
}

// An edge p0–p1 crossing triangle abc's plane (its ends at least margin on either side) at a point
// inside the triangle at least margin from its sides: the faces cross there.
static bool fc_edge_pierces(ori_v3 p0, ori_v3 p1, ori_v3 a, ori_v3 b, ori_v3 c, double margin)
{
    ori_v3 n = ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a));
    double nn = ori_v3_norm(n);
    if (!(nn > 0.0)) return false;
    n = ori_v3_scale(n, 1.0 / nn);
    double d0 = ori_v3_dot(n, ori_v3_sub(p0, a)), d1 = ori_v3_dot(n, ori_v3_sub(p1, a));
    if (!((d0 >= margin && d1 <= -margin) || (d0 <= -margin && d1 >= margin))) return false;
    ori_v3 x = ori_v3_add(p0, ori_v3_scale(ori_v3_sub(p1, p0), d0 / (d0 - d1)));
    const ori_v3 t[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        ori_v3 u = t[i], w = t[(i + 1) % 3];
        double len = ori_v3_norm(ori_v3_sub(w, u));
        if (!(ori_v3_dot(ori_v3_cross(ori_v3_sub(w, u), ori_v3_sub(x, u)), n) >= margin * len)) return false;
    }
    return true;
}

// Brute force on triangles: an edge of one piercing the other well inside is a penetrating pair,
// whether the faces share a vertex or not.
static void fc_brute_triangles(const ori_collider *col, const fc_faces *fv, const ori_v3 *pos, double margin,
                               const fc_pairs *got)
{
    int F = ori_collider_face_count(col);
    for (int f = 0; f < F; ++f)
        for (int g = f + 1; g < F; ++g) {
            if (fv->n[f] != 3 || fv->n[g] != 3) continue;
            bool cross = false;
            for (int s = 0; s < 2 && !cross; ++s) {
                const int *e = fv->v[s ? g : f], *t = fv->v[s ? f : g];
                for (int i = 0; i < 3 && !cross; ++i)
                    cross = fc_edge_pierces(pos[e[i]], pos[e[(i + 1) % 3]], pos[t[0]], pos[t[1]], pos[t[2]], margin);
            }
            if (!cross) continue;
            bool found = false;
            for (int i = 0; i < got->n && !found; ++i)
                found = got->k[i].face_a == f && got->k[i].face_b == g && got->k[i].kind == ORI_CONTACT_PENETRATING;
            if (!found) {
                fprintf(stderr, "triangles %d and %d cross (an edge through the other), not reported penetrating\n", f, g);
                abort();
            }
        }
}

// One state: checked twice (determinism), against brute force and at a smaller clearance.
static void fc_state(fk_bytes *b, const ori_pattern *p, ori_collider *col, double c, const fc_faces *fv, const ori_v3 *pos)
{
    static fc_pairs one, two, small;
    ori_collision_result r, r2;
    ori_error err;
    ori_status st = ori_collider_check(col, pos, &r, &err);
    fc_refusal(st, &err);
    if (st != ORI_OK) {
        if (ori_collider_check(col, pos, &r2, &err) != st) abort(); // deterministic refusal
        return;
    }
    fc_check_result(col, c, &r, &one);
    if (ori_collider_check(col, pos, &r2, &err) != ORI_OK) abort();
    fc_check_result(col, c, &r2, &two);
    if (r.collides != r2.collides || r.min_clearance != r2.min_clearance || r.contact_count != r2.contact_count ||
        r.clearance_faces[0] != r2.clearance_faces[0] || r.clearance_faces[1] != r2.clearance_faces[1] ||
        r.has_witness != r2.has_witness || (r.has_witness && (r.witness.x != r2.witness.x || r.witness.y != r2.witness.y ||
                                                              r.witness.z != r2.witness.z)))
        abort();
    if (one.n != two.n) abort();
    for (int i = 0; i < one.n; ++i)
        if (!fc_same_contact(&one.k[i], &two.k[i])) abort();
    double L = ori_pattern_diagonal(p);
    double tol = 1e-9 * L + 4.0 * r.tolerance;
    fc_brute(col, fv, pos, c, tol, &r, &one);
    fc_brute_triangles(col, fv, pos, fmax(1e-6 * L, 8.0 * r.tolerance), &one);

    // A smaller clearance: the same penetrating and touching pairs, NEAR a subset.
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = p;
    cd.clearance = c * fk_range(b, 0.0, 1.0);
    ori_collider *lo = NULL;
    if (ori_collider_create(&cd, &lo, &err) != ORI_OK) abort(); // the same pattern, a good clearance
    ori_collision_result rs;
    if (ori_collider_check(lo, pos, &rs, &err) != ORI_OK) abort(); // the same positions passed
    fc_check_result(lo, cd.clearance, &rs, &small);
    if (rs.penetrating != r.penetrating || rs.touching != r.touching) abort();
    if (rs.near > r.near) abort();
    if (!(fabs(rs.min_clearance - r.min_clearance) <= 1e-12 * L || rs.min_clearance == r.min_clearance)) abort();
    for (int i = 0, j = 0; i < small.n; ++i) {
        const ori_contact *k = &small.k[i];
        while (j < one.n && (one.k[j].face_a < k->face_a || (one.k[j].face_a == k->face_a && one.k[j].face_b < k->face_b))) {
            // dropped at the smaller clearance: only a NEAR pair not nearer than it
            if (one.k[j].kind != ORI_CONTACT_NEAR || one.k[j].distance < cd.clearance - 1e-12 * L) abort();
            j++;
        }
        if (j >= one.n || one.k[j].face_a != k->face_a || one.k[j].face_b != k->face_b) abort();
        if (one.k[j].kind != k->kind) abort();
        if (k->kind == ORI_CONTACT_NEAR && fabs(one.k[j].distance - k->distance) > 1e-12 * L) abort();
        j++;
    }
    ori_collider_destroy(lo);

    // The cloud of proximity, with hostile spacing and distance.
    ori_cloud_def cl = ori_default_cloud_def();
    cl.spacing = fc_length(b, L);
    cl.distance = fc_length(b, L);
    cl.max_points = 1 + fk_u16(b) % 4000;
    ori_cloud_result cr;
    st = ori_collider_cloud(col, pos, &cl, &cr, &err);
    fc_refusal(st, &err);
    double least = ORI_TOL_CONTACT_REL * L;
    bool bad = !(cl.spacing >= least) || !isfinite(cl.spacing) || !(cl.distance >= least) || !isfinite(cl.distance);
    if (bad && st != ORI_ERR_RANGE) abort();
    if (st != ORI_OK) {
        if (st != ORI_ERR_RANGE && st != ORI_ERR_LIMIT) abort();
        return;
    }
    if (cr.points < 0 || cr.points > cl.max_points || cr.point_pairs < 0) abort();
    if (ori_collider_cloud_pair_count(col) != cr.face_pairs) abort();
    int64_t sum = 0;
    double least_d = INFINITY;
    for (int i = 0; i < cr.face_pairs; ++i) {
        ori_cloud_pair cp = ori_collider_cloud_pair(col, i);
        int F = ori_collider_face_count(col);
        if (!(cp.face_a >= 0 && cp.face_a < cp.face_b && cp.face_b < F)) abort();
        if (i > 0) {
            ori_cloud_pair q = ori_collider_cloud_pair(col, i - 1);
            if (q.face_a > cp.face_a || (q.face_a == cp.face_a && q.face_b >= cp.face_b)) abort();
        }
        if (ori_collider_adjacent(col, cp.face_a, cp.face_b)) abort();
        if (cp.point_pairs <= 0) abort();
        if (!(cp.distance < cl.distance) || !(cp.distance >= r.min_clearance - tol)) abort();
        if (ori_v3_norm(ori_v3_sub(cp.points[0], cp.points[1])) > cp.distance + tol) abort();
        sum += cp.point_pairs;
        least_d = fmin(least_d, cp.distance);
    }
    if (sum != cr.point_pairs) abort();
    if (cr.face_pairs == 0 ? cr.min_distance != INFINITY : cr.min_distance != least_d) abort();
}

static bool fc_same_event(const ori_collision_event *x, const ori_collision_event *y)
{
    if (x->collides != y->collides) return false;
    if (!x->collides) return true;
    return x->frame == y->frame && x->fold == y->fold && x->step == y->step && x->drive_rad == y->drive_rad &&
           x->time == y->time && fc_same_contact(&x->contact, &y->contact);
}

// A motion check's event: frames before the first colliding one are clean (checked one by one).
static void fc_event(ori_collider *col, const ori_trajectory *t, double c, ori_status st, const ori_error *err,
                     const ori_collision_event *ev)
{
    fc_refusal(st, err);
    if (st != ORI_OK) return;
    int F = ori_collider_face_count(col), n = ori_trajectory_frame_count(t);
    int clean = n;
    if (ev->collides) {
        if (!(ev->frame >= 0 && ev->frame < n)) abort();
        const ori_contact *k = &ev->contact;
        if (!(k->face_a >= 0 && k->face_a < k->face_b && k->face_b < F) || !k->collides) abort();
        if (k->adjacent != ori_collider_adjacent(col, k->face_a, k->face_b)) abort();
        if (k->kind == ORI_CONTACT_NEAR && (k->adjacent || !(k->distance < c))) abort();
        if (!isfinite(k->distance) || !isfinite(k->point.x) || !isfinite(k->point.y) || !isfinite(k->point.z)) abort();
        if (!isfinite(ev->drive_rad) || !isfinite(ev->time) || ev->states_solved < 0) abort();
        clean = ev->frame;
    }
    if (clean > 24) clean = 24; // bounded work
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(ori_collider_vertex_count(col) + 1));
    for (int f = 0; f < clean; ++f) {
        ori_trajectory_frame_vertices(t, f, pos);
        ori_collision_result r;
        ori_error e2;
        if (ori_collider_check(col, pos, &r, &e2) == ORI_OK && r.collides) {
            fprintf(stderr, "frame %d collides (faces %d, %d) but the motion check says %s%d\n", f,
                    ori_collider_contact_count(col) ? ori_collider_contact(col, 0).face_a : -1,
                    ori_collider_contact_count(col) ? ori_collider_contact(col, 0).face_b : -1,
                    ev->collides ? "first at frame " : "clean, frames ", ev->collides ? ev->frame : n);
            abort();
        }
    }
    free(pos);
}

static ori_collision_motion_def fc_check_def(fk_bytes *b)
{
    ori_collision_motion_def cm = ori_default_collision_motion_def();
    switch (fk_u8(b) % 8) {
    case 0: case 1: break; // the default (also past the input's end)
    case 2: cm.drive_tol_rad = 0.0; break;
    case 3: cm.drive_tol_rad = -1.0; break;
    case 4: cm.drive_tol_rad = NAN; break;
    case 5: cm.drive_tol_rad = INFINITY; break;
    default: cm.drive_tol_rad = fk_range(b, 1e-6, 0.2); break;
    }
    return cm;
}

static void fc_motion_checks(fk_bytes *b, const ori_pattern *p, const ori_mechanism *m, ori_collider *col, double c,
                             const fc_faces *fv)
{
    int locks[8];
    ori_motion_def d = fk_fold(b, m, locks);
    if (d.step_rad < 10.0 * FK_DEG) d.step_rad = 10.0 * FK_DEG;
    ori_motion *mo = NULL;
    ori_error err;
    int V = ori_mechanism_vertex_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    if (ori_motion_solve(m, &d, &mo, &err) == ORI_OK) {
        fk_check_motion(m, mo);
        ori_trajectory t = ori_trajectory_of_motion(m, &d, mo);
        int n = ori_trajectory_frame_count(&t);
        // A few states checked in full: the last frame, the middle one, a fuzzed one.
        for (int q = 0; q < 3 && n > 0; ++q) {
            int k = q == 0 ? n - 1 : q == 1 ? n / 2 : fk_u8(b) % n;
            ori_trajectory_frame_vertices(&t, k, pos);
            fc_state(b, p, col, c, fv, pos);
        }
        ori_collision_motion_def cm = fc_check_def(b);
        ori_collision_event ev, ev2;
        ori_status st = ori_collision_check_motion(col, m, &d, mo, &cm, &ev, &err);
        if (!(cm.drive_tol_rad > 0.0) && st != ORI_ERR_RANGE) abort();
        fc_event(col, &t, c, st, &err, &ev);
        // Again through the trajectory view: the same answer (determinism and the view at once).
        ori_status st2 = ori_collision_check_trajectory(col, &t, &cm, &ev2, &err);
        if (st2 != st || (st == ORI_OK && !fc_same_event(&ev, &ev2))) abort();
        ori_motion_destroy(mo);
    }

    // A hostile state: fold angles that need not close (each vertex placed by the face nearest the
    // fixed one), some vertices moved anywhere, sometimes a coordinate that is not finite (refused
    // with ORI_ERR_RANGE). Triangles stay planar, so single vertices give crossings here.
    if (fk_u8(b) & 1) {
        int E = ori_mechanism_edge_count(m);
        double *a = malloc(sizeof(double) * (size_t)(E + 1));
        for (int e = 0; e < E; ++e) a[e] = fk_range(b, -ORI_PI, ORI_PI);
        ori_mechanism_vertex_positions(m, a, 0, ori_rigid_identity(), pos);
        free(a);
        double L = ori_pattern_diagonal(p);
        int moves = fk_u8(b) % 4;
        for (int i = 0; i < moves; ++i) {
            int v = fk_u8(b) % V;
            pos[v].x += fk_range(b, -L, L);
            pos[v].y += fk_range(b, -L, L);
            pos[v].z += fk_range(b, -L, L);
        }
        uint8_t poison = fk_u8(b);
        if (poison >= 240) {
            static const double bad[3] = {NAN, INFINITY, -INFINITY};
            pos[poison % V].z = bad[poison % 3];
            ori_collision_result r;
            ori_error e2;
            ori_status st = ori_collider_check(col, pos, &r, &e2);
            fc_refusal(st, &e2);
            if (st != ORI_ERR_RANGE) abort();
        } else {
            fc_state(b, p, col, c, fv, pos);
        }
    }

    // A one- or two-fold sequence, checked as a record.
    if (fk_u8(b) & 1) {
        char text[2048];
        int nf = 1 + (fk_u8(b) & 1);
        size_t len = (size_t)snprintf(text, sizeof text, "{\"pattern\":\"x.fold\",\"folds\":[");
        for (int k = 0; k < nf; ++k) {
            ori_motion_def s = fk_fold(b, m, locks);
            double step = s.step_rad < 20.0 * FK_DEG ? 20.0 * FK_DEG : s.step_rad;
            len += (size_t)snprintf(text + len, sizeof text - len, "%s{\"fix\":%d,\"drive\":%d,\"to\":%.17g,\"step\":%.17g}",
                                    k ? "," : "", s.fixed_face, s.driven_edge, s.to_rad / FK_DEG, step / FK_DEG);
        }
        snprintf(text + len, sizeof text - len, "]}");
        ori_sequence *s = NULL;
        if (ori_sequence_parse(text, strlen(text), &s, &err) != ORI_OK) abort(); // our own text
        ori_record *rec = NULL;
        if (ori_sequence_run(s, m, NULL, ori_rigid_identity(), &rec, &err) == ORI_OK) {
            ori_trajectory t = ori_trajectory_of_record(rec);
            ori_collision_motion_def cm = fc_check_def(b);
            ori_collision_event ev, ev2;
            ori_status st = ori_collision_check_record(col, rec, &cm, &ev, &err);
            if (!(cm.drive_tol_rad > 0.0) && st != ORI_ERR_RANGE) abort();
            fc_event(col, &t, c, st, &err, &ev);
            if (st == ORI_OK && ev.collides && !(ev.fold >= 0 && ev.fold < nf && ev.step >= 0)) abort();
            ori_status st2 = ori_collision_check_trajectory(col, &t, &cm, &ev2, &err);
            if (st2 != st || (st == ORI_OK && !fc_same_event(&ev, &ev2))) abort();
            ori_record_destroy(rec);
        }
        ori_sequence_destroy(s);
    }

    // A bounded target fold (several degrees of freedom), checked as a multifold.
    if (fk_u8(b) & 1) {
        ori_target_fold_def td = ori_default_target_fold_def();
        int F = ori_mechanism_face_count(m), E = ori_mechanism_edge_count(m);
        td.fixed_face = F > 0 ? fk_u8(b) % F : 0;
        td.fraction = fk_range(b, 0.0, 1.0);
        td.step_rad = fk_range(b, 20.0, 90.0) * FK_DEG;
        td.max_steps = 1 + fk_u8(b) % 8;
        int tl[2], nl = fk_u8(b) % 3;
        for (int i = 0; i < nl; ++i) tl[i] = E > 0 ? fk_u8(b) % E : 0;
        td.locked_edges = tl;
        td.locked_count = nl;
        ori_multifold *mf = NULL;
        if (ori_target_fold_solve(m, &td, &mf, &err) == ORI_OK) {
            ori_trajectory t = ori_trajectory_of_multifold(mf, tl, nl);
            ori_collision_motion_def cm = fc_check_def(b);
            ori_collision_event ev, ev2;
            ori_status st = ori_collision_check_multifold(col, mf, tl, nl, &cm, &ev, &err);
            if (!(cm.drive_tol_rad > 0.0) && st != ORI_ERR_RANGE) abort();
            fc_event(col, &t, c, st, &err, &ev);
            ori_status st2 = ori_collision_check_trajectory(col, &t, &cm, &ev2, &err);
            if (st2 != st || (st == ORI_OK && !fc_same_event(&ev, &ev2))) abort();
            ori_multifold_destroy(mf);
        }
    }
    free(pos);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    (void)fk_check_written; // (fuzz_kin.h's, for the targets that write frames)
    fk_bytes b = {data, size, 0};
    ori_pattern *p = NULL;
    ori_mechanism *m = NULL;
    if (!fk_mechanism(&b, &p, &m)) {
        if (ori_alloc_live_count() != 0) abort();
        return 0;
    }
    int F = ori_pattern_face_count(p);
    static fc_faces fv;
    bool small = F <= FC_MAX_FACES;
    for (int f = 0; f < F && small; ++f) {
        fv.n[f] = ori_pattern_face_vertices(p, f, fv.v[f], 16);
        small = fv.n[f] <= 16;
    }
    if (small) {
        double L = ori_pattern_diagonal(p);
        ori_collider_def cd = ori_default_collider_def();
        cd.pattern = p;
        cd.clearance = fc_length(&b, L);
        ori_collider *col = NULL;
        ori_error err;
        ori_status st = ori_collider_create(&cd, &col, &err);
        fc_refusal(st, &err);
        bool bad = !(cd.clearance >= 0.0) || !isfinite(cd.clearance);
        if (bad != (st == ORI_ERR_RANGE)) abort();
        if (st == ORI_OK) {
            if (ori_collider_face_count(col) != F || ori_collider_vertex_count(col) != ori_pattern_vertex_count(p)) abort();
            for (int f = 0; f < F; ++f)
                for (int g = f + 1; g < F; ++g)
                    if (ori_collider_adjacent(col, f, g) != ori_collider_adjacent(col, g, f)) abort();
            fc_motion_checks(&b, p, m, col, cd.clearance, &fv);
        }
        ori_collider_destroy(col);
    }
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
