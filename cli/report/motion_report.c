// Where a fold stops, as JSON: one builder for `orikin fold --json`, its -o marker
// "orikin:partial" and the studio's POST /api/fold.
#include "report.h"

json_t *cli_motion_block_json(const ori_motion *mo)
{
    ori_motion_block b;
    if (!ori_motion_block_of(mo, &b)) return json_null();
    json_t *o = json_object();
    bool limit = b.kind == ORI_BLOCK_CREASE_LIMIT;
    json_object_set_new(o, "kind", json_string(limit                               ? "crease_limit"
                                               : b.kind == ORI_BLOCK_STEP_LIMIT ? "step_limit"
                                                                                : "singular"));
    json_object_set_new(o, "drive_deg", json_real(ori_rad_to_deg_output(b.drive_rad)));
    json_object_set_new(o, "edge", limit ? json_integer(b.edge) : json_null());
    json_object_set_new(o, "edge_angle_deg", limit ? json_real(ori_rad_to_deg_output(b.edge_angle_rad)) : json_null());
    json_t *s = json_array();
    for (int i = 0; !limit && i < b.singular_count; ++i) json_array_append_new(s, json_integer(b.singular_edges[i]));
    json_object_set_new(o, "singular_edges", s);
    return o;
}

bool cli_motion_partial(const ori_motion *mo, const cli_collision *col)
{
    return cli_collides(col) || ori_motion_block_of(mo, NULL);
}

json_t *cli_motion_dof_json(const ori_motion *mo)
{
    int d = ori_motion_dof(mo);
    return d >= 0 ? json_integer(d) : json_null();
}
