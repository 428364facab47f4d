// Self-collision along a fold or a sequence, as `orikin fold` and `orikin sequence` report it
// and the studio's POST /api/fold and /api/sequence answer it.
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report.h"

ori_status cli_collision_check_motion(ori_collider *c, const ori_mechanism *m, const ori_motion_def *def,
                                      const ori_motion *mo, ori_progress_fn *progress, void *user, cli_collision *out,
                                      ori_error *err)
{
    memset(out, 0, sizeof *out);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    cd.progress = progress;
    cd.progress_user = user;
    ori_status st = ori_collision_check_motion(c, m, def, mo, &cd, &out->ev, err);
    out->checked = st == ORI_OK;
    return st;
}

ori_status cli_collision_check_record(ori_collider *c, const ori_record *r, ori_progress_fn *progress, void *user,
                                      cli_collision *out, ori_error *err)
{
    memset(out, 0, sizeof *out);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    cd.progress = progress;
    cd.progress_user = user;
    ori_status st = ori_collision_check_record(c, r, &cd, &out->ev, err);
    out->checked = st == ORI_OK;
    out->progress = st == ORI_OK && out->ev.collides && ori_record_fold_is_targets(r, out->ev.fold);
    return st;
}

bool cli_collides(const cli_collision *c) { return c->checked && c->ev.collides; }

int cli_collide_frames(const cli_collision *c, int frames)
{
    if (!cli_collides(c)) return frames;
    return c->ev.frame < frames ? c->ev.frame : frames;
}

json_t *cli_collision_json(const cli_collision *c, bool with_fold)
{
    if (!cli_collides(c)) return json_null();
    const ori_collision_event *e = &c->ev;
    json_t *o = json_object();
    if (with_fold) json_object_set_new(o, "fold", json_integer(e->fold + 1));
    json_object_set_new(o, "step", json_integer(e->step));
    if (c->progress) json_object_set_new(o, "progress", json_real(e->drive_rad));
    else json_object_set_new(o, "drive_deg", json_real(ori_rad_to_deg_output(e->drive_rad)));
    json_object_set_new(o, "faces", json_pack("[ii]", e->contact.face_a, e->contact.face_b));
    json_object_set_new(o, "point", json_pack("[fff]", e->contact.point.x, e->contact.point.y, e->contact.point.z));
    return o;
}

static const char *verb(const ori_contact *k)
{
    if (k->kind == ORI_CONTACT_NEAR) return "come closer than the clearance";
    if (k->kind == ORI_CONTACT_TOUCHING) return "touch (within the clearance)";
    return k->stacked ? "pass through each other (stacked layers)" : "penetrate";
}

void cli_collision_describe(const cli_collision *c, bool with_fold, char *buf, size_t size)
{
    const ori_collision_event *e = &c->ev;
    char fold[32] = "";
    if (with_fold) snprintf(fold, sizeof fold, "fold %d, ", e->fold + 1);
    char at[64];
    if (c->progress) snprintf(at, sizeof at, "progress %.9f", e->drive_rad);
    else snprintf(at, sizeof at, "drive %.6f deg", ori_rad_to_deg(e->drive_rad));
    snprintf(buf, size, "faces %d and %d %s at %sstep %d, %s, at (%.6g, %.6g, %.6g)", e->contact.face_a,
             e->contact.face_b, verb(&e->contact), fold, e->step, at, e->contact.point.x, e->contact.point.y,
             e->contact.point.z);
}

// --- one state (orikin collide --json; GET /api/collide) ----------------------------------------

static json_t *pack_v3(ori_v3 v)
{
    return json_pack("[fff]", v.x, v.y, v.z);
}


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

json_t *cli_collide_json(const char *file, int frame, const char *state, bool posed, const ori_collider *c,
                         const ori_collision_result *r, double clearance, const ori_cloud_result *cr, double cloud_spacing,
                         double cloud_distance)
{
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(file));
    json_object_set_new(o, "frame", frame >= 0 ? json_integer(frame) : json_null());
    if (state) json_object_set_new(o, "state", json_string(state));
    json_object_set_new(o, "posed", json_boolean(posed));
    json_object_set_new(o, "faces", json_integer(ori_collider_face_count(c)));
    json_object_set_new(o, "collides", json_boolean(r->collides));
    json_object_set_new(o, "pairs", pairs_json(c, true));
    json_object_set_new(o, "touching", pairs_json(c, false));
    json_object_set_new(o, "min_clearance", isfinite(r->min_clearance) ? json_real(r->min_clearance) : json_null());
    json_object_set_new(o, "witness", r->has_witness ? pack_v3(r->witness) : json_null());
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
        json_object_set_new(x, "point", pack_v3(k.point));
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
