// orikin animate: the whole motion of a fold, a fold sequence or a multi-frame FOLD file as an
// animated GIF, every frame an exact state at its time.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "color_args.h"
#include "progress.h"
#include "render_args.h"
#include "state_args.h"

// Most frames one animation may have.
#define MAX_FRAMES 10000

typedef struct anim_frames {
    const cli_state *st;
    const cli_motion *m;
    const cli_colors *colors; // --color: every frame's values, or NULL
} anim_frames;

// --color: frame index's values (face_count or edge_count of them).
static ori_status values_of(int index, const double **face_values, const double **edge_values, void *user, ori_error *error)
{
    (void)error;
    const anim_frames *a = user;
    const cli_colors *c = a->colors;
    if (c->face_values) *face_values = c->face_values + (size_t)index * (size_t)a->m->face_count;
    else *edge_values = c->edge_values + (size_t)index * (size_t)a->m->edge_count;
    return ORI_OK;
}

static ori_status frame_of(int index, ori_state_view *out, void *user, ori_error *error)
{
    (void)error;
    const anim_frames *a = user;
    out->pattern = a->st->pattern;
    out->positions = a->m->positions + (size_t)index * (size_t)a->m->vertex_count;
    out->fold_angles_rad = a->m->angles ? a->m->angles + (size_t)index * (size_t)a->m->edge_count : NULL;
    return ORI_OK;
}

static int run(int argc, char **argv)
{
    const char *cmd = "animate";
    cli_state_args sa;
    cli_state_args_init(&sa);
    cli_render_args ra;
    cli_render_args_init(&ra);
    const char *out = NULL;
    bool json = false, has_fps = false, has_duration = false;
    double fps = 15.0, duration = 3.0;
    cli_collide_opts co;
    memset(&co, 0, sizeof co);
    cli_color_kind color = CLI_COLOR_NONE;
    int rc;
    for (int i = 1; i < argc; ++i) {
        int took = cli_state_option(cmd, argc, argv, &i, &sa, &rc);
        if (took < 0) return rc;
        if (took) continue;
        took = cli_color_option(cmd, argc, argv, &i, &color, &rc);
        if (took < 0) return rc;
        if (took) continue;
        if (strcmp(argv[i], "--view") == 0) return cli_usage(cmd, "an animation shows the 3D view (no --view)");
        took = cli_collide_option(cmd, argc, argv, &i, &co);
        if (took < 0) return CLI_EXIT_USAGE;
        if (took) continue;
        took = cli_render_option(cmd, argc, argv, &i, &ra, false, &rc);
        if (took < 0) return rc;
        if (took) continue;
        const char *o = argv[i];
        if (strcmp(o, "-o") == 0) {
            if (out) return cli_usage(cmd, "-o given twice");
            if (!(out = cli_option_value(cmd, argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(o, "--fps") == 0 || strcmp(o, "--duration") == 0) {
            bool is_fps = o[2] == 'f';
            if (is_fps ? has_fps : has_duration) return cli_usage(cmd, "%s given twice", o);
            const char *v = cli_option_value(cmd, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            double x;
            if (is_fps) {
                if (!cli_parse_double(v, &x) || x < 1.0 || x > 50.0)
                    return cli_usage(cmd, "--fps needs a frame rate from 1 to 50 per second, got '%s'", v);
                fps = x;
                has_fps = true;
            } else {
                if (!cli_parse_double(v, &x) || !(x > 0.0) || x > 3600.0)
                    return cli_usage(cmd, "--duration needs a time in seconds, above 0 and at most 3600, got '%s'", v);
                duration = x;
                has_duration = true;
            }
        } else if (strcmp(o, "--json") == 0) {
            json = true;
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage(cmd, "unknown option %s", o);
        } else {
            return cli_usage(cmd, "one IN only");
        }
    }
    if ((rc = cli_state_finish(cmd, &sa)) != CLI_EXIT_OK) return rc;
    if (!out) return cli_usage(cmd, "missing -o OUT.gif");
    size_t n = strlen(out);
    if (n < 4 || strcmp(out + n - 4, ".gif") != 0) return cli_usage(cmd, "-o %s: an animation is written as .gif", out);
    if (sa.source == CLI_STATE_FRAME && sa.has_frame)
        return cli_usage(cmd, "animate shows every frame of IN: --frame only starts a fold given with fold options");
    if (sa.has_at) return cli_usage(cmd, "animate shows the whole sequence: --at picks one instant (use orikin render)");
    int frames = (int)lround(fps * duration) + 1;
    if (frames > MAX_FRAMES)
        return cli_usage(cmd, "--fps %g over --duration %g gives %d frames, more than %d", fps, duration, frames, MAX_FRAMES);

    cli_state st;
    if ((rc = cli_state_load(cmd, &sa, false, &st)) != CLI_EXIT_OK) return rc;
    // The motion is drawn whole; a collision along it is noted (orikin fold and orikin sequence
    // stop there instead).
    cli_collision coll;
    if ((rc = cli_state_collisions(cmd, &st, &co, &coll)) != CLI_EXIT_OK) {
        cli_state_free(&st);
        return rc;
    }
    cli_motion m;
    if ((rc = cli_state_motion(cmd, &st, frames, &m)) != CLI_EXIT_OK) {
        cli_state_free(&st);
        return rc;
    }
    ori_gif_def def = ori_default_gif_def();
    void *texture = NULL;
    if ((rc = cli_render_def(cmd, &ra, &def.render, &texture)) != CLI_EXIT_OK) {
        cli_motion_free(&m);
        cli_state_free(&st);
        return rc;
    }
    def.render.view = ORI_RENDER_3D;
    if (texture && !st.has_flat) {
        ori_buffer_free(texture);
        cli_motion_free(&m);
        cli_state_free(&st);
        return cli_input_fail(cmd, sa.path, "--texture needs a flat crease pattern for texture coordinates; this is a folded form");
    }
    cli_colors colors;
    memset(&colors, 0, sizeof colors);
    if (color != CLI_COLOR_NONE && (rc = cli_colors_motion(cmd, &sa, &st, &m, color, &colors)) != CLI_EXIT_OK) {
        ori_buffer_free(texture);
        cli_motion_free(&m);
        cli_state_free(&st);
        return rc;
    }
    anim_frames af = {&st, &m, color != CLI_COLOR_NONE ? &colors : NULL};
    if (color != CLI_COLOR_NONE) { // one bar over the whole motion: its range is every frame's
        def.frame_values = values_of;
        def.render.values.min = colors.min;
        def.render.values.max = colors.max;
    }
    def.frame_count = m.count;
    def.frame = frame_of;
    def.user = &af;
    // The frames span the motion evenly over --duration.
    def.fps = (m.count - 1) / duration;
    if (def.fps < 1.0) def.fps = 1.0;
    if (def.fps > 100.0) def.fps = 100.0;
    cli_progress pr;
    cli_progress_begin(&pr, cmd, "drawing frames");
    def.progress = cli_progress_fn;
    def.progress_user = &pr;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    ori_status s = ori_gif_write(&def, &data, &size, &err);
    cli_progress_end(&pr);
    if (s == ORI_OK) s = ori_file_write_atomic(out, data, size, &err);
    if (s != ORI_OK) {
        const char *file = s == ORI_ERR_PARSE ? ra.texture : s == ORI_ERR_IO ? out : sa.path;
        rc = cli_input_error(cmd, file, &err);
        if (s == ORI_ERR_INTERNAL || s == ORI_ERR_NOMEM) rc = CLI_EXIT_INTERNAL;
    } else if (json) {
        json_t *o = json_object();
        json_object_set_new(o, "output", json_string(out));
        json_object_set_new(o, "frames", json_integer(m.count));
        json_object_set_new(o, "fps", json_real(def.fps));
        json_object_set_new(o, "duration_s", json_real(duration));
        json_object_set_new(o, "width", json_integer(def.render.width));
        json_object_set_new(o, "height", json_integer(def.render.height));
        json_object_set_new(o, "bytes", json_integer((json_int_t)size));
        json_object_set_new(o, "collision", cli_collision_json(&coll, st.source == CLI_STATE_SEQUENCE));
        json_object_set_new(o, "color", color != CLI_COLOR_NONE ? cli_colors_json(&colors) : json_null());
        cli_print_json(o);
    } else {
        printf("wrote %s: %d frames of %s over %g s (%dx%d gif, %zu bytes)", out, m.count, sa.path, duration,
               def.render.width, def.render.height, size);
        if (color != CLI_COLOR_NONE)
            printf("; %s of %d %s from %.4g to %.4g over the motion", cli_color_name(color), colors.shown,
                   colors.face_values ? "faces" : "creases", colors.min, colors.max);
        printf("\n");
        if (cli_collides(&coll)) {
            char why[256];
            cli_collision_describe(&coll, st.source == CLI_STATE_SEQUENCE, why, sizeof why);
            double t = coll.ev.time;
            if (coll.progress) t = coll.ev.drive_rad; // a fold in one of the modes: times are its progress
            else if (st.source == CLI_STATE_FOLD && m.count > 1) t = coll.ev.time / (ori_motion_frame_count(st.motion) - 1);
            printf("note: the motion collides: %s, %.3g s into the animation; the frames after it show faces "
                   "passing through each other (orikin %s stops there)\n",
                   why, duration * t / (m.duration > 0.0 ? m.duration : 1.0), st.source == CLI_STATE_SEQUENCE ? "sequence" : "fold");
        }
    }
    ori_buffer_free(data);
    ori_buffer_free(texture);
    cli_colors_free(&colors);
    cli_motion_free(&m);
    cli_state_free(&st);
    return rc;
}

const cli_command cli_cmd_animate = {
    "animate",
    "an animated GIF of a fold, a fold sequence or a multi-frame FOLD file",
    "usage: orikin animate IN [fold options] [--fps N] [--duration S] [--size WxH]\n"
    "                      [--camera iso|top|front|side|bottom] [--yaw DEG] [--pitch DEG]\n"
    "                      [--roll DEG] [--perspective] [--front COLOR] [--back COLOR]\n"
    "                      [--texture IMG.png] [--edges] [--grid]\n"
    "                      [--color strain|fold-angle|target-error] [--json] -o OUT.gif\n"
    "\n"
    "Draw the whole motion as an animated GIF in the 3D view (see orikin render). IN is a fold\n"
    "sequence SEQ.json, a FOLD file with the options of `orikin fold`, or a FOLD file with\n"
    "several frames (its folded states). The frames are spread evenly in time over the motion\n"
    "and each is an exact state at its time (solved, not interpolated; a FOLD file holds\n"
    "nothing between its frames, so there each frame shows the stored state nearest in time).\n"
    "The camera is fitted once to the whole motion, so that the shape does not jump; the last\n"
    "frame stays one second before the loop starts again. One palette of 256 colours (median\n"
    "cut) serves every frame. A progress bar appears on stderr when drawing takes over a second.\n"
    "\n"
    "options:\n"
    "  --fix F --drive E --to DEG [--from DEG] [--lock E1,...] [--solver S] [--linear L]\n"
    "  [--frame N]          a fold (see orikin fold), from frame N's state. F: a face index,\n"
    "                       name (Obj12) or @x,y; E: a crease index or @x,y; --lock 3,@0.5,1,9\n"
    CLI_STATE_MODES_HELP
    "  --fps N              frames per second, 1 to 50 (default 15)\n"
    "  --duration S         seconds the motion takes, up to 3600 (default 3)\n"
    "  --size WxH           image size in pixels (default 800x600)\n"
    "  --camera, --yaw, --pitch, --roll, --perspective, --front, --back, --texture, --edges,\n"
    "  --grid               as for orikin render\n"
    "  --no-collisions      do not check the motion for self-collision (a fold or a sequence\n"
    "                       is checked as by orikin fold; a collision is noted, the motion drawn)\n"
    "  --clearance D        faces sharing no vertex closer than D collide too\n"
    CLI_COLOR_HELP
    "                       One bar serves the whole motion (its range: every frame's values);\n"
    "                       strain needs a FOLD file's frames (fold --compliant --all-frames -o)\n"
    "  --json               print {output, frames, fps, duration_s, width, height, bytes,\n"
    "                       collision: {fold, step, drive_deg, faces, point} | null,\n"
    "                       color: {quantity, per, shown, min, max, labels} | null}\n"
    "  -o OUT.gif           the animation\n"
    "\n"
    "example: orikin animate examples/open-corner.seq.json --yaw 90 --grid -o open-corner.gif\n",
    run,
    NULL,
};
