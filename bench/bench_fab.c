// Fabrication scenarios: (1) the tolerance analysis of the thesis' open corner with gold hinges
// (examples/patterns/open-corner-gold.fold: 1 mm sheet, first fold of the diagonal to 90° with the
// down crease locked, face 4 fixed), σ = 1 µm on every vertex: 10,000 samples on two threads and
// 2,000 on one, samples per second; (2) the GDSII mask of a 100×100 Miura-ori (mm cells, every
// crease a hinge strip): layout and stream; (3) the device chain on the open corner: design,
// fold, hinge sizing (actuate), mask and cutting files, in milliseconds.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench.h"
#include <orikin/fab.h>
#include <orikin/generate.h>

#define DEG (ORI_PI / 180.0)

static const char *corner_path(void) { return ORI_BENCH_SOURCE_DIR "/examples/patterns/open-corner-gold.fold"; }

static int tolerance(void)
{
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_file(corner_path(), &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
        printf("   %s: %s\n", corner_path(), err.message);
        ori_fold_destroy(doc);
        return 1;
    }
    int locks[1] = {11};
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 4;
    md.driven_edge = 12;
    md.to_rad = 90.0 * DEG;
    md.step_rad = 1.0 * DEG;
    md.locked_edges = locks;
    md.locked_count = 1;
    int runs[2][2] = {{10000, 2}, {2000, 1}};
    for (int r = 0; r < 2; ++r) {
        ori_tolerance_def td = ori_default_tolerance_def();
        td.pattern = p;
        td.motion = &md;
        td.vertex_sigma = 1.0; // µm: the pattern's unit
        td.samples = runs[r][0];
        td.threads = runs[r][1];
        td.seed = 2026;
        ori_tolerance *t = NULL;
        double t0 = bench_now(), c0 = bench_cpu_now();
        ori_status st = ori_tolerance_run(&td, &t, &err);
        double t1 = bench_now(), c1 = bench_cpu_now();
        if (st != ORI_OK) {
            printf("   tolerance: %s\n", err.message);
            ori_pattern_destroy(p);
            ori_fold_destroy(doc);
            return 1;
        }
        ori_tolerance_stats pos = ori_tolerance_stats_of(t, ORI_TOLERANCE_METRIC_POSITION);
        ori_tolerance_stats nrm = ori_tolerance_stats_of(t, ORI_TOLERANCE_METRIC_NORMAL);
        printf("   tolerance open corner (diagonal to 90 deg, 1-deg steps), sigma 1 um: %d samples on %d thread%s in %.2f s "
               "wall (%.2f s CPU): %.0f samples/s; position error mean %.3g um, p99 %.3g um; normal p99 %.3g deg; %d failed\n",
               td.samples, td.threads, td.threads == 1 ? "" : "s", t1 - t0, c1 - c0, td.samples / (t1 - t0), pos.mean, pos.p99,
               nrm.p99 / DEG, ori_tolerance_failed_count(t));
        fflush(stdout);
        ori_tolerance_destroy(t);
    }
    // hinge widths too (5 %), each sample's fold to 180 deg sized
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    md.to_rad = ORI_PI;
    md.step_rad = 10.0 * DEG;
    ori_tolerance_def td = ori_default_tolerance_def();
    td.pattern = p;
    td.motion = &md;
    td.vertex_sigma = 1.0;
    td.design = &dd;
    td.width_sigma_rel = 0.05;
    td.samples = 1000;
    td.threads = 2;
    ori_tolerance *t = NULL;
    double t0 = bench_now(), c0 = bench_cpu_now();
    ori_status st = ori_tolerance_run(&td, &t, &err);
    double t1 = bench_now(), c1 = bench_cpu_now();
    if (st == ORI_OK) {
        ori_tolerance_stats cur = ori_tolerance_stats_of(t, ORI_TOLERANCE_METRIC_CURRENT);
        printf("   tolerance with 5 %% hinge widths, each fold to 180 deg (10-deg steps) sized: %d samples on 2 threads in "
               "%.2f s wall (%.2f s CPU): %.0f samples/s; current %.4g mA nominal, mean %.4g, sd %.3g, p99 %.4g mA\n",
               td.samples, t1 - t0, c1 - c0, td.samples / (t1 - t0), 1e3 * ori_tolerance_nominal_current(t), 1e3 * cur.mean,
               1e3 * cur.sd, 1e3 * cur.p99);
    } else {
        printf("   tolerance with widths: %s\n", err.message);
    }
    ori_tolerance_destroy(t);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return st == ORI_OK ? 0 : 1;
}

static int mask(void)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = 100;
    g.cols = 100;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return 1;
    ori_fab_def d = ori_default_fab_def();
    d.pattern = p;
    d.meters_per_unit = 1e-3;
    ori_fab_layout *l = NULL;
    double t0 = bench_now();
    if (ori_fab_layout_create(&d, &l, &err) != ORI_OK) {
        printf("   mask: %s\n", err.message);
        ori_pattern_destroy(p);
        return 1;
    }
    double t1 = bench_now();
    size_t n = 0;
    unsigned char *bytes = ori_gds_write(l, NULL, &n, &err);
    double t2 = bench_now();
    char *svg = ori_cut_svg_write(p, NULL, &err);
    double t3 = bench_now();
    printf("   mask 100x100 Miura (%d faces, %d edges): layout %d shapes in %.3f s, GDSII %.1f MB in %.3f s; laser SVG %.1f MB "
           "in %.3f s\n",
           ori_pattern_face_count(p), ori_pattern_edge_count(p), ori_fab_shape_count(l), t1 - t0, n / 1e6, t2 - t1,
           strlen(svg) / 1e6, t3 - t2);
    ori_buffer_free(svg);
    ori_buffer_free(bytes);
    ori_fab_layout_destroy(l);
    ori_pattern_destroy(p);
    return bytes ? 0 : 1;
}

static int chain(void)
{
    double t0 = bench_now();
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_file(corner_path(), &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) return 1;
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    dd.pattern = p;
    ori_design *design = NULL;
    ori_mechanism *m = NULL;
    ori_motion *mo = NULL;
    ori_sizing *z = NULL;
    ori_fab_layout *l = NULL;
    int rc = 1;
    ori_mechanism_def mdef = ori_default_mechanism_def();
    mdef.pattern = p;
    int locks[1] = {11};
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 4;
    md.driven_edge = 12;
    md.to_rad = ORI_PI;
    md.step_rad = 10.0 * DEG;
    md.locked_edges = locks;
    md.locked_count = 1;
    if (ori_design_create(&dd, &design, &err) != ORI_OK || ori_mechanism_create(&mdef, &m, &err) != ORI_OK ||
        ori_motion_solve(m, &md, &mo, &err) != ORI_OK)
        goto done;
    double t1 = bench_now();
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = design;
    sd.mechanism = m;
    sd.motion = mo;
    sd.driven_edge = 12;
    if (ori_sizing_solve(&sd, &z, &err) != ORI_OK) goto done;
    double t2 = bench_now();
    ori_fab_def fd = ori_default_fab_def();
    fd.pattern = p;
    fd.design = design;
    fd.fixed_face = 4;
    if (ori_fab_layout_create(&fd, &l, &err) != ORI_OK) goto done;
    size_t n = 0;
    unsigned char *bytes = ori_gds_write(l, NULL, &n, &err);
    char *dxf = ori_dxf_write(p, NULL, &err);
    double t3 = bench_now();
    printf("   device chain, open corner: load + design + fold to 180 deg %.2f ms, sizing (actuate) %.2f ms, mask (%zu bytes) "
           "and DXF %.2f ms: %.2f ms in all; needs %.4g mA\n",
           1e3 * (t1 - t0), 1e3 * (t2 - t1), n, 1e3 * (t3 - t2), 1e3 * (t3 - t0), 1e3 * ori_sizing_summary_of(z).current_needed_a);
    ori_buffer_free(dxf);
    ori_buffer_free(bytes);
    rc = 0;
done:
    if (rc) printf("   chain: %s\n", err.message);
    ori_fab_layout_destroy(l);
    ori_sizing_destroy(z);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_design_destroy(design);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

static int run(void) { return tolerance() | mask() | chain(); }

const bench_scenario bench_fab = {
    "fab", "tolerance of the thesis open corner (10,000 samples, sigma 1 um), GDSII mask of a 100x100 Miura, the device chain",
    run};
