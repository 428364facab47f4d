// DOF scenario: ori_mechanism_dof at the flat state (rank there, then the generic probe) of every
// generator's tessellation at a few sizes. The probe's branch enumeration used to be exponential
// (125 s for a 2 × 2 square twist) and the sparse rank quadratic in the nullity (31 s for a flat
// 100 × 100 Miura-ori); both are bounded now (docs/kinematics.md, section 3).
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <time.h>

#include "bench.h"
#include <orikin/generate.h>
#include <orikin/kinematics.h>

static int one(const char *name, ori_tessellation kind, int rows, int cols)
{
    ori_generate_def g = ori_default_generate_def(kind);
    g.rows = rows;
    g.cols = cols;
    if (kind == ORI_TESS_KRESLING) g.sides = cols; // rows = storeys, cols = polygon sides
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return 1;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) {
        ori_pattern_destroy(p);
        return 1;
    }
    ori_dof_def d = ori_default_dof_def();
    ori_dof_result r;
    double t0 = bench_now(), c0 = bench_cpu_now();
    ori_status st = ori_mechanism_dof(m, &d, &r, &err);
    double t1 = bench_now(), c1 = bench_cpu_now();
    if (st == ORI_OK) {
        char nearby[64];
        if (r.undetermined) snprintf(nearby, sizeof nearby, "undetermined");
        else snprintf(nearby, sizeof nearby, "%d%s", r.generic_dof, r.rigid ? " (rigid)" : "");
        printf("   %-13s %3dx%-3d %6d creases: %7.3f s wall (%7.3f s CPU); rank %d, dof %d, nearby %s, %d probe "
               "solves, %s\n",
               name, rows, cols, r.unknowns, t1 - t0, c1 - c0, r.rank, r.dof, nearby, r.probe_solves,
               r.dense ? "dense SVD" : "sparse");
    }
    fflush(stdout);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return st != ORI_OK;
}

static int run(void)
{
    int bad = 0;
    bad |= one("miura", ORI_TESS_MIURA, 10, 10);
    bad |= one("miura", ORI_TESS_MIURA, 32, 32);
    bad |= one("miura", ORI_TESS_MIURA, 100, 100);
    bad |= one("yoshimura", ORI_TESS_YOSHIMURA, 4, 4);
    bad |= one("yoshimura", ORI_TESS_YOSHIMURA, 12, 12);
    bad |= one("waterbomb", ORI_TESS_WATERBOMB, 4, 4);
    bad |= one("waterbomb", ORI_TESS_WATERBOMB, 8, 8);
    bad |= one("square-twist", ORI_TESS_SQUARE_TWIST, 2, 2);
    bad |= one("square-twist", ORI_TESS_SQUARE_TWIST, 4, 4);
    bad |= one("kresling", ORI_TESS_KRESLING, 3, 6);
    bad |= one("kresling", ORI_TESS_KRESLING, 8, 8);
    return bad;
}

const bench_scenario bench_dof = {"dof", "degrees of freedom at the flat state of each generator's tessellation", run};
