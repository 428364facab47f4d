// Local flat-foldability at a tolerance, as `orikin check` reports it and the studio's
// GET /api/check answers it.
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"

void cli_check_run(const ori_pattern *p, const char *file, bool has_tolerance, double tolerance_deg, cli_check *out)
{
    memset(out, 0, sizeof *out);
    out->has_tolerance = has_tolerance;
    out->tolerance_deg = has_tolerance ? tolerance_deg : 0.0;
    ori_flat_check_def cd = ori_default_flat_check_def();
    cd.tolerance_rad = ori_deg_to_rad(out->tolerance_deg);
    out->report = ori_flat_check_pattern(p, &cd);
    // Without a tolerance: do the failures look like the rounding of a drawing? Check again at
    // the hint tolerance (0.01°) and count the failures it explains.
    int failed = ori_flat_report_failed_count(out->report);
    if (!has_tolerance && failed > 0) {
        ori_flat_check_def hd = ori_default_flat_check_def();
        hd.record_vertices = false;
        hd.tolerance_rad = ORI_FLAT_ROUNDING_HINT_RAD;
        ori_flat_report *h = ori_flat_check_pattern(p, &hd);
        out->rounding_failures = ori_flat_report_within_count(h);
        out->rounding_max_rad = ori_flat_report_max_deviation(h);
        ori_flat_report_destroy(h);
    }
    int rounded = out->rounding_failures;
    if (rounded > 0 && rounded == failed)
        snprintf(out->hint, sizeof out->hint,
                 "every failure is below 0.01 deg (largest sector change needed %.3g deg): the drawing looks "
                 "rounded; try 'orikin check %s --tolerance 0.01' or 'orikin regularize %s -o exact.fold'",
                 ori_rad_to_deg_output(out->rounding_max_rad), file, file);
    else if (rounded > 0)
        snprintf(out->hint, sizeof out->hint,
                 "%d of the %d failures are below 0.01 deg (rounding; see --tolerance and regularize); the "
                 "others are real",
                 rounded, failed);
}

void cli_check_free(cli_check *c)
{
    ori_flat_report_destroy(c->report);
    memset(c, 0, sizeof *c);
}

static json_t *count_json(ori_mv_count c)
{
    if (c.overflow || c.count > (uint64_t)INT64_MAX) return json_null();
    return json_integer((json_int_t)c.count);
}

static json_t *vertex_json(const ori_pattern *p, const ori_flat_report *rep, int i, int *edges, double *sectors)
{
    ori_vertex_report r = ori_flat_report_vertex(rep, i);
    int n = ori_flat_report_vertex_creases(rep, i, edges, sectors, r.degree);
    json_t *o = json_object();
    json_object_set_new(o, "vertex", json_integer(r.vertex));
    json_object_set_new(o, "degree", json_integer(r.degree));
    json_t *cr = json_array(), *sd = json_array();
    char *letters = malloc((size_t)n + 1);
    for (int k = 0; k < n; ++k) {
        json_array_append_new(cr, json_integer(edges[k]));
        json_array_append_new(sd, json_real(ori_rad_to_deg_output(sectors[k])));
        letters[k] = ori_assignment_to_char(ori_pattern_edge(p, edges[k]).assignment);
    }
    letters[n] = '\0';
    json_object_set_new(o, "creases", cr);
    json_object_set_new(o, "assignment", json_string(letters));
    free(letters);
    json_object_set_new(o, "sectors_deg", sd);
    json_object_set_new(o, "sector_sum_deg", json_real(ori_rad_to_deg_output(r.sector_sum_rad)));
    json_object_set_new(o, "kawasaki", json_boolean(r.kawasaki));
    json_object_set_new(o, "maekawa", r.maekawa == ORI_FLAT_UNDETERMINED ? json_null() : json_boolean(r.maekawa == ORI_FLAT_YES));
    json_object_set_new(o, "big_little_big", json_boolean(r.big_little_big));
    json_object_set_new(o, "mv_count", count_json(r.mv_count));
    if (r.mv_count.overflow) json_object_set_new(o, "mv_count_overflow", json_true());
    json_object_set_new(o, "assignment_valid", json_boolean(r.assignment_valid));
    if (r.unassigned > 0) {
        json_object_set_new(o, "unassigned", json_integer(r.unassigned));
        json_object_set_new(o, "unassigned_completions", count_json(r.completions));
    }
    json_object_set_new(o, "cone", json_boolean(r.cone));
    json_object_set_new(o, "flat_foldable", json_boolean(r.flat_foldable));
    json_object_set_new(o, "within_tolerance", json_boolean(r.within_tolerance));
    json_object_set_new(o, "deviation_deg", json_real(ori_rad_to_deg_output(r.deviation_rad)));
    return o;
}

json_t *cli_check_json(const cli_check *c, const char *file, int frame, const ori_pattern *p)
{
    const ori_flat_report *rep = c->report;
    int max_degree = 1;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        int d = ori_pattern_vertex_degree(p, v);
        if (d > max_degree) max_degree = d;
    }
    int *edges = malloc(sizeof(int) * (size_t)max_degree);
    double *sectors = malloc(sizeof(double) * (size_t)max_degree);
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "frame", json_integer(frame));
    json_object_set_new(out, "locally_flat_foldable", json_boolean(ori_flat_report_flat_foldable(rep)));
    json_object_set_new(out, "interior_vertices", json_integer(ori_flat_report_interior_count(rep)));
    json_object_set_new(out, "failed_vertices", json_integer(ori_flat_report_failed_count(rep)));
    json_object_set_new(out, "tolerance_deg", json_real(c->tolerance_deg));
    json_object_set_new(out, "within_tolerance_vertices", json_integer(ori_flat_report_within_count(rep)));
    json_object_set_new(out, "max_deviation_deg", json_real(ori_rad_to_deg_output(ori_flat_report_max_deviation(rep))));
    json_object_set_new(out, "rounding_failures", json_integer(c->rounding_failures));
    json_object_set_new(out, "hint", c->hint[0] ? json_string(c->hint) : json_null());
    json_t *vs = json_array();
    for (int i = 0; i < ori_flat_report_vertex_count(rep); ++i) json_array_append_new(vs, vertex_json(p, rep, i, edges, sectors));
    json_object_set_new(out, "vertices", vs);
    json_t *viol = json_array();
    for (int i = 0; i < ori_flat_report_violation_count(rep); ++i) {
        ori_flat_violation x = ori_flat_report_violation(rep, i);
        json_t *o = json_object();
        json_object_set_new(o, "vertex", json_integer(x.vertex));
        json_object_set_new(o, "rule", json_string(ori_flat_rule_name(x.rule)));
        if (x.edge != ORI_NULL_INDEX) json_object_set_new(o, "edge", json_integer(x.edge));
        json_object_set_new(o, "detail", json_string(x.detail));
        json_array_append_new(viol, o);
    }
    json_object_set_new(out, "violations", viol);
    free(edges);
    free(sectors);
    return out;
}
