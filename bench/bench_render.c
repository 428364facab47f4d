// Render scenario: a folded N×N Miura-ori (N = 25, 50, 100) drawn in 3D at 1920×1080 to PNG
// and to SVG, and exported to glTF with a 100-step animation (the fold from 5° to 175°). The
// folds are solved first and not timed. Targets for 100×100: PNG under 0.5 s, the animated glTF
// under 1 s, memory linear in the number of faces (heap peak per face reported for each N).
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include <orikin/generate.h>
#include <orikin/kinematics.h>
#include <orikin/render.h>

static ori_pattern *miura(int n)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = n;
    g.cols = n;
    g.width = 1.0;
    g.height = sqrt(1.25);
    g.angle_rad = atan2(1.0, 0.5);
    ori_pattern *p = NULL;
    ori_error err;
    return ori_generate(&g, &p, NULL, &err) == ORI_OK ? p : NULL;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int one(int n)
{
    ori_pattern *p = miura(n);
    if (!p) return 1;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    ori_error err;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) return 1;
    int drive = ori_pattern_find_edge(p, (n / 2) * (n + 1) + n / 2, (n / 2 + 1) * (n + 1) + n / 2);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    // Setup (not timed): flat → 5°, then 5° → 175° in 100 output steps.
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = sg * ori_deg_to_rad(5.0);
    d.step_rad = ori_deg_to_rad(5.0);
    ori_motion *start = NULL, *mo = NULL;
    if (ori_motion_solve(m, &d, &start, &err) != ORI_OK || ori_motion_verdict_of(start) != ORI_MOTION_VALID) return 1;
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * ori_deg_to_rad(175.0);
    d.step_rad = ori_deg_to_rad(170.0 / 100.0);
    if (ori_motion_solve(m, &d, &mo, &err) != ORI_OK || ori_motion_verdict_of(mo) != ORI_MOTION_VALID) return 1;
    int K = ori_motion_frame_count(mo), F = ori_pattern_face_count(p), V = ori_pattern_vertex_count(p);
    // The picture: the state at 120° (frame nearest to it).
    int shown = (int)lround((120.0 - 5.0) / 1.7);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V);
    ori_motion_frame_vertices(mo, shown, pos);
    ori_state_view sv = {p, pos, ori_motion_frame_angles(mo, shown)};
    ori_render_def rd = ori_default_render_def();
    rd.view = ORI_RENDER_3D;
    rd.width = 1920;
    rd.height = 1080;
    double sec[2], cpu[2], peak[2];
    size_t bytes[2];
    for (int f = 0; f < 2; ++f) {
        rd.format = f == 0 ? ORI_IMAGE_PNG : ORI_IMAGE_SVG;
        void *data = NULL;
        int64_t base = ori_alloc_live_bytes();
        ori_alloc_reset_peak();
        double t0 = bench_now(), c0 = cpu_now();
        if (ori_render_image(&sv, &rd, &data, &bytes[f], &err) != ORI_OK) return 1;
        sec[f] = bench_now() - t0;
        cpu[f] = cpu_now() - c0;
        peak[f] = (double)(ori_alloc_peak_bytes() - base);
        ori_buffer_free(data);
    }
    // The animation: face poses of every step, then the GLB.
    int64_t base = ori_alloc_live_bytes();
    ori_alloc_reset_peak();
    double t0 = bench_now(), c0 = cpu_now();
    ori_rigid *poses = malloc(sizeof(ori_rigid) * (size_t)K * (size_t)F);
    double *times = malloc(sizeof(double) * (size_t)K);
    for (int k = 0; k < K; ++k) {
        ori_motion_frame_face_poses(mo, k, poses + (size_t)k * F);
        times[k] = (double)k / (K - 1);
    }
    ori_mesh *mesh = NULL;
    if (ori_mesh_create(&sv, &mesh, &err) != ORI_OK) return 1;
    ori_export_def ed = ori_default_export_def();
    ed.format = ORI_MESH_GLB;
    ed.keyframe_count = K;
    ed.keyframe_times_s = times;
    ed.keyframe_poses = poses;
    void *glb = NULL;
    size_t glb_size = 0;
    if (ori_mesh_export(mesh, &ed, &glb, &glb_size, &err) != ORI_OK) return 1;
    double t1 = bench_now(), c1 = cpu_now();
    double glb_peak = (double)(ori_alloc_peak_bytes() - base);
    peak[0] -= 4.0 * rd.width * rd.height; // the image itself
    printf("   %3dx%-3d %5d faces: PNG 1920x1080 %.3f s (%.3f s CPU, %.1f MB, heap peak %.0f B/face + the image); "
           "SVG %.3f s (%.3f s CPU, %.1f MB, heap peak %.0f B/face); GLB %d keyframes %.3f s (%.3f s CPU, %.1f MB, heap peak "
           "%.0f B/face); RSS peak %.0f MB\n",
           n, n, F, sec[0], cpu[0], bytes[0] / 1e6, peak[0] / F, sec[1], cpu[1], bytes[1] / 1e6, peak[1] / F, K, t1 - t0, c1 - c0,
           glb_size / 1e6, glb_peak / F, (double)bench_peak_rss() / 1e6);
    fflush(stdout);
    ori_buffer_free(glb);
    ori_mesh_destroy(mesh);
    free(poses);
    free(times);
    free(pos);
    ori_motion_destroy(mo);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return 0;
}

static int run(void)
{
    int sizes[3] = {25, 50, 100};
    int bad = 0;
    for (int k = 0; k < 3; ++k) bad |= one(sizes[k]);
    return bad;
}

const bench_scenario bench_render = {"render", "folded Miura-ori NxN: 1920x1080 PNG and SVG, GLB with a 100-step animation",
                                     run};
