// Self-collision scenario: an R×C Miura-ori (R = 100 rows; C = 100 and 200 columns, 10,000 and
// 20,000 faces) folded by its middle zig-zag crease from 5° to 175° in 100 output steps (as
// bench_miura). Figures: one state's check (the 90° frame: broad-phase pairs against n(n−1)/2,
// CPU time, heap per face), and the whole 100-step motion checked frame by frame with the
// layer orders (ori_collision_check_motion), against the solve of the same motion: the ratio
// collision time / solve time (CPU and wall; issue 28 asks for at most 0.5 on the 100 x 100).
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include <orikin/collision.h>
#include <orikin/generate.h>
#include <orikin/kinematics.h>

#include "collision/collision_internal.h" // col_collider_set_reference: today's checker, for the figure before

static int one(int rows, int cols)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = rows;
    g.cols = cols;
    g.width = 1.0;
    g.height = sqrt(1.25);
    g.angle_rad = atan2(1.0, 0.5);
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return 1;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) return 1;
    int i = cols / 2, j = rows / 2;
    int drive = ori_pattern_find_edge(p, j * (cols + 1) + i, (j + 1) * (cols + 1) + i);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = sg * ori_deg_to_rad(5.0);
    d.step_rad = ori_deg_to_rad(5.0);
    ori_motion *start = NULL, *mo = NULL;
    if (ori_motion_solve(m, &d, &start, &err) != ORI_OK || ori_motion_verdict_of(start) != ORI_MOTION_VALID) return 1;
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * ori_deg_to_rad(175.0);
    d.step_rad = ori_deg_to_rad(170.0 / 100.0);
    double sc0 = bench_cpu_now(), sw0 = bench_now();
    if (ori_motion_solve(m, &d, &mo, &err) != ORI_OK || ori_motion_verdict_of(mo) != ORI_MOTION_VALID) return 1;
    double solve_cpu = bench_cpu_now() - sc0, solve_wall = bench_now() - sw0;
    int nf = ori_mechanism_face_count(m), nv = ori_mechanism_vertex_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)nv);
    int frame90 = 50; // 5 + 50 · 1.7 = 90°
    ori_motion_frame_vertices(mo, frame90, pos);

    int64_t base = ori_alloc_live_bytes();
    ori_alloc_reset_peak();
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = p;
    ori_collider *c = NULL;
    if (ori_collider_create(&cd, &c, &err) != ORI_OK) return 1;
    ori_collision_result r;
    double best = INFINITY;
    for (int rep = 0; rep < 5; ++rep) {
        double t0 = bench_cpu_now();
        if (ori_collider_check(c, pos, &r, &err) != ORI_OK) return 1;
        best = fmin(best, bench_cpu_now() - t0);
    }
    double heap = (double)(ori_alloc_peak_bytes() - base);
    double all = (double)nf * (nf - 1) / 2.0;
    printf("   %3dx%-3d %5d faces, one state at %.0f deg: %.1f ms CPU (best of 5), %lld broad-phase pairs of %.3g "
           "(n^2/2; %.2g of it, %.1f per face), %lld exact distances, %d touching, %d penetrating, min clearance "
           "%.4g; heap %.0f bytes per face (%.1f MB)\n",
           rows, cols, nf, fabs(ori_rad_to_deg(ori_motion_frame_drive(mo, frame90))), 1e3 * best,
           (long long)r.candidate_pairs, all, (double)r.candidate_pairs / all, (double)r.candidate_pairs / nf,
           (long long)r.distance_pairs, r.touching, r.penetrating, r.min_clearance, heap / nf, heap / 1e6);
    fflush(stdout);

    ori_alloc_reset_peak();
    base = ori_alloc_live_bytes();
    ori_collision_motion_def md2 = ori_default_collision_motion_def();
    ori_collision_event ev;
    double t0 = bench_cpu_now(), w0 = bench_now();
    if (ori_collision_check_motion(c, m, &d, mo, &md2, &ev, &err) != ORI_OK) return 1;
    double t1 = bench_cpu_now(), w1 = bench_now();
    printf("   %3dx%-3d whole motion 5->175 deg, %d frames: %.3f s CPU (%.3f s wall), %.1f ms per frame, %s; heap %.0f "
           "bytes per face\n",
           rows, cols, ori_motion_frame_count(mo), t1 - t0, w1 - w0, 1e3 * (t1 - t0) / ori_motion_frame_count(mo),
           ev.collides ? "COLLIDES" : "clean", (double)(ori_alloc_peak_bytes() - base) / nf);
    col_collider_set_reference(c, true);
    ori_collision_event ev0;
    double r0 = bench_cpu_now(), rw0 = bench_now();
    if (ori_collision_check_motion(c, m, &d, mo, &md2, &ev0, &err) != ORI_OK) return 1;
    double r1 = bench_cpu_now(), rw1 = bench_now();
    col_collider_set_reference(c, false);
    printf("   %3dx%-3d the same with the reference checker (every step from nothing): %.3f s CPU (%.3f s wall), %s, "
           "%s\n",
           rows, cols, r1 - r0, rw1 - rw0, ev0.collides ? "COLLIDES" : "clean",
           memcmp(&ev0, &ev, sizeof ev) == 0 ? "the same event" : "ANOTHER EVENT");
    printf("   %3dx%-3d solve of the same motion %.3f s CPU (%.3f s wall): collision / solve = %.2f CPU, %.2f wall\n",
           rows, cols, solve_cpu, solve_wall, (t1 - t0) / solve_cpu, (w1 - w0) / solve_wall);
    fflush(stdout);
    free(pos);
    ori_collider_destroy(c);
    ori_motion_destroy(mo);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return ev.collides;
}

static int run(void)
{
    int bad = one(32, 32);
    bad |= one(100, 100);
    bad |= one(100, 200);
    return bad;
}

const bench_scenario bench_collision = {"collision", "self-collision of a folding Miura-ori (10,000 and 20,000 faces)", run};
