// Self-collision along a fold or a sequence, as `orikin fold` and `orikin sequence` report it
// and the studio's POST /api/fold and /api/sequence answer it.
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
