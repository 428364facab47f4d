// The verdict and the JSON of a regularization (orikin regularize --json, POST /api/regularize):
// one refusal text and one object, so that both front ends answer alike by construction.
#include <stdio.h>

#include "report.h"

const char *cli_regularize_refusal(const ori_regularize_result *r, const ori_regularize_def *def, char *buf, size_t size)
{
    bool rigid = def->rigid || def->rigid_only;
    const char *goal = rigid ? "rigidly foldable" : "flat-foldable";
    if (r->odd_vertex != ORI_NULL_INDEX)
        snprintf(buf, size, "interior vertex %d has an odd number of creases: no move makes it flat-foldable", r->odd_vertex);
    else if (r->refused)
        snprintf(buf, size,
                 "the nearest %s pattern moves vertex %d by %.3g of the sheet size, more than %.3g (--max-move): "
                 "the drawing is not a rounded version of one",
                 goal, r->max_move_vertex, r->max_move_rel, def->max_move_rel);
    else if (r->stopped && r->iterations == 0)
        snprintf(buf, size, "stopped at the budget before the first iteration: nothing moved yet");
    else if (r->stopped && def->rigid_only)
        snprintf(buf, size, "stopped at the budget after %d iterations, still converging: the best found has rigid defect %.3g",
                 r->iterations, r->rigid_after);
    else if (r->stopped && rigid)
        snprintf(buf, size,
                 "stopped at the budget after %d iterations, still converging: the best found misses Kawasaki by %.3g "
                 "rad, rigid defect %.3g",
                 r->iterations, r->kawasaki_after_rad, r->rigid_after);
    else if (r->stopped)
        snprintf(buf, size, "stopped at the budget after %d iterations, still converging: the best found misses Kawasaki by %.3g rad",
                 r->iterations, r->kawasaki_after_rad);
    else if (r->crossing_edge != ORI_NULL_INDEX)
        snprintf(buf, size, "the nearest %s pattern would make edges cross (%s): the drawing's topology does not allow it",
                 goal, r->crossing);
    else if (r->against_edge != ORI_NULL_INDEX)
        snprintf(buf, size,
                 "crease %d folds against its assignment in the only motion its degree-4 vertices allow (the "
                 "assignment does not fit the geometry)",
                 r->against_edge);
    else if (!def->rigid_only && !r->flat_foldable && r->check_vertex != ORI_NULL_INDEX)
        snprintf(buf, size, "Kawasaki holds after the moves, but vertex %d is not flat-foldable (%s): %s", r->check_vertex,
                 ori_flat_rule_name((ori_flat_rule)r->check_rule), r->check_detail);
    else if (!r->converged && def->rigid_only)
        snprintf(buf, size, "no rigidly foldable pattern was found near this one (rigid defect %.3g after %d iterations)",
                 r->rigid_after, r->iterations);
    else if (!r->converged && rigid)
        snprintf(buf, size,
                 "no rigidly foldable pattern was found near this one (Kawasaki %.3g rad, rigid defect %.3g after %d "
                 "iterations)",
                 r->kawasaki_after_rad, r->rigid_after, r->iterations);
    else if (!r->converged)
        snprintf(buf, size, "no flat-foldable pattern was found near this one (Kawasaki %.3g rad after %d iterations)",
                 r->kawasaki_after_rad, r->iterations);
    else return NULL;
    return buf;
}

bool cli_regularize_request_error(const ori_regularize_def *def, const char *max_move_name, char *buf, size_t size)
{
    if (!(def->max_move_rel > 0.0 && def->max_move_rel <= 1.0))
        snprintf(buf, size, "%s needs a fraction of the sheet size in (0, 1], got %g", max_move_name, def->max_move_rel);
    else if (def->rigid && def->rigid_only)
        snprintf(buf, size, "--rigid and --rigid-only exclude each other (--rigid-only: without Kawasaki)");
    else return false;
    return true;
}

bool cli_regularize_pattern_error(const ori_pattern *p, int frame, char *buf, size_t size)
{
    if (!ori_pattern_is_folded_form(p) && !ori_pattern_is_3d(p)) return false;
    snprintf(buf, size, "frame %d is a folded form: regularize needs a flat crease pattern", frame);
    return true;
}

static json_t *index_or_null(int i) { return i == ORI_NULL_INDEX ? json_null() : json_integer(i); }

json_t *cli_regularize_json(const char *file, const ori_regularize_def *def, const ori_regularize_result *r,
                            const char *why, const char *output)
{
    bool rigid = def->rigid || def->rigid_only;
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(file));
    json_object_set_new(o, "rigid", json_boolean(rigid));
    json_object_set_new(o, "converged", json_boolean(r->converged));
    json_object_set_new(o, "refused", json_boolean(r->refused));
    json_object_set_new(o, "reason", why ? json_string(why) : json_null());
    json_object_set_new(o, "interior_vertices", json_integer(r->interior_vertices));
    json_object_set_new(o, "unknowns", json_integer(r->unknowns));
    json_object_set_new(o, "equations", json_integer(r->equations));
    json_object_set_new(o, "iterations", json_integer(r->iterations));
    json_object_set_new(o, "stopped", json_boolean(r->stopped));
    json_object_set_new(o, "moved_vertices", json_integer(r->moved_vertices));
    json_object_set_new(o, "max_move_rel", json_real(r->max_move_rel));
    json_object_set_new(o, "max_move_vertex", index_or_null(r->max_move_vertex));
    json_object_set_new(o, "rms_move_rel", json_real(r->rms_move_rel));
    json_object_set_new(o, "max_move_allowed_rel", json_real(def->max_move_rel));
    json_object_set_new(o, "kawasaki_before_deg", json_real(ori_rad_to_deg_output(r->kawasaki_before_rad)));
    json_object_set_new(o, "kawasaki_after_deg", json_real(ori_rad_to_deg_output(r->kawasaki_after_rad)));
    json_object_set_new(o, "crossing_edge", index_or_null(r->crossing_edge));
    json_object_set_new(o, "rigid_before", rigid ? json_real(r->rigid_before) : json_null());
    json_object_set_new(o, "rigid_after", rigid ? json_real(r->rigid_after) : json_null());
    json_object_set_new(o, "mode_vertices", rigid ? json_integer(r->mode_vertices) : json_null());
    json_object_set_new(o, "against_edge", index_or_null(r->against_edge));
    json_object_set_new(o, "rigid_only", json_boolean(def->rigid_only));
    json_object_set_new(o, "equal_tolerance_deg", json_real(ori_rad_to_deg_output(r->equal_tolerance_rad)));
    json_object_set_new(o, "ties", json_integer(r->ties));
    json_object_set_new(o, "parallels_kept", json_boolean(r->parallels_kept));
    json_object_set_new(o, "sides_moved", json_boolean(r->sides_moved));
    json_object_set_new(o, "flat_foldable", def->rigid_only ? json_null() : json_boolean(r->flat_foldable));
    json_object_set_new(o, "check_vertex", index_or_null(r->check_vertex));
    json_object_set_new(o, "output", output ? json_string(output) : json_null());
    return o;
}
