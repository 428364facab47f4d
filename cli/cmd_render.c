// orikin render: a picture of any state — the crease pattern (thesis line styles) or the posed
// sheet in 3D — as SVG, PDF or PNG.
#include <stdlib.h>
#include <string.h>

#include "color_args.h"
#include "render_args.h"
#include "state_args.h"

static int run(int argc, char **argv)
{
    const char *cmd = "render";
    cli_state_args sa;
    cli_state_args_init(&sa);
    cli_render_args ra;
    cli_render_args_init(&ra);
    const char *out = NULL;
    bool json = false;
    cli_color_kind color = CLI_COLOR_NONE;
    int rc;
    for (int i = 1; i < argc; ++i) {
        int took = cli_state_option(cmd, argc, argv, &i, &sa, &rc);
        if (took < 0) return rc;
        if (took) continue;
        took = cli_render_option(cmd, argc, argv, &i, &ra, true, &rc);
        if (took < 0) return rc;
        if (took) continue;
        took = cli_color_option(cmd, argc, argv, &i, &color, &rc);
        if (took < 0) return rc;
        if (took) continue;
        if (strcmp(argv[i], "-o") == 0) {
            if (out) return cli_usage(cmd, "-o given twice");
            if (!(out = cli_option_value(cmd, argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(cmd, "unknown option %s", argv[i]);
        } else {
            return cli_usage(cmd, "one IN only");
        }
    }
    if ((rc = cli_state_finish(cmd, &sa)) != CLI_EXIT_OK) return rc;
    if (!out) return cli_usage(cmd, "missing -o OUT.svg, OUT.pdf or OUT.png");
    ori_image_format format = ori_image_format_from_path(out);
    if (format == ORI_IMAGE_UNKNOWN) return cli_usage(cmd, "-o %s: unknown image format (use .svg, .pdf or .png)", out);
    if (ra.has_view && ra.view == ORI_RENDER_CREASES && ra.only_3d)
        return cli_usage(cmd, "%s is for the 3D view, not --view cp", ra.only_3d);
    if (ra.has_view && ra.view == ORI_RENDER_3D && ra.labels) return cli_usage(cmd, "--labels is for the crease view (--view cp)");
    if (ra.has_view && ra.view == ORI_RENDER_CREASES && sa.source != CLI_STATE_FRAME)
        return cli_usage(cmd, "--view cp draws the crease pattern: it takes no fold options or --at");

    // The view: as asked; else the crease pattern for a crease-pattern frame (its fold angles may
    // be targets rather than a state), 3D otherwise.
    ori_render_view view = ORI_RENDER_3D;
    bool decided = ra.has_view || ra.only_3d || ra.labels || sa.source != CLI_STATE_FRAME;
    if (ra.has_view) view = ra.view;
    else if (ra.labels) view = ORI_RENDER_CREASES;
    cli_state st;
    if ((rc = cli_state_load(cmd, &sa, decided && view == ORI_RENDER_3D, &st)) != CLI_EXIT_OK) return rc;
    if (!decided) view = st.cp_frame ? ORI_RENDER_CREASES : ORI_RENDER_3D;
    if (view == ORI_RENDER_CREASES && !st.has_flat) {
        cli_state_free(&st);
        return cli_input_fail(cmd, sa.path, "frame %d is a folded form without a crease pattern: use --view 3d", sa.frame);
    }
    cli_colors colors;
    memset(&colors, 0, sizeof colors);
    if (color != CLI_COLOR_NONE && (rc = cli_colors_load(cmd, &sa, &st, color, &colors)) != CLI_EXIT_OK) {
        cli_state_free(&st);
        return rc;
    }
    ori_render_def def = ori_default_render_def();
    void *texture = NULL;
    if ((rc = cli_render_def(cmd, &ra, &def, &texture)) != CLI_EXIT_OK) {
        cli_colors_free(&colors);
        cli_state_free(&st);
        return rc;
    }
    if (color != CLI_COLOR_NONE) def.values = cli_colors_map(&colors);
    def.view = view;
    def.format = format;
    def.face_orders = st.face_orders; // a frame's own layer order of stacked faces
    def.face_order_count = st.face_order_count;
    if (texture && !st.has_flat) {
        ori_buffer_free(texture);
        cli_colors_free(&colors);
        cli_state_free(&st);
        return cli_input_fail(cmd, sa.path, "--texture needs a flat crease pattern for texture coordinates; this is a folded form");
    }
    ori_state_view sv = cli_state_view(&st);
    if (view == ORI_RENDER_CREASES) sv.positions = NULL;
    ori_error err;
    ori_status s = ori_render_file(&sv, &def, out, &err);
    if (s != ORI_OK) {
        const char *file = s == ORI_ERR_PARSE ? ra.texture : s == ORI_ERR_IO ? out : sa.path;
        rc = cli_input_error(cmd, file, &err);
        if (s == ORI_ERR_INTERNAL || s == ORI_ERR_NOMEM) rc = CLI_EXIT_INTERNAL;
    } else {
        int failing = -1;
        if (view == ORI_RENDER_CREASES) {
            ori_flat_report *r = ori_flat_check_pattern(st.pattern, NULL);
            failing = ori_flat_report_failed_count(r);
            ori_flat_report_destroy(r);
        }
        const char *view_name = view == ORI_RENDER_CREASES ? "crease pattern" : "3D view";
        if (json) {
            json_t *o = json_object();
            json_object_set_new(o, "output", json_string(out));
            json_object_set_new(o, "format", json_string(ori_image_format_name(format)));
            json_object_set_new(o, "view", json_string(view == ORI_RENDER_CREASES ? "cp" : "3d"));
            json_object_set_new(o, "width", json_integer(def.width));
            json_object_set_new(o, "height", json_integer(def.height));
            json_object_set_new(o, "state", json_string(st.label));
            json_object_set_new(o, "faces", json_integer(ori_pattern_face_count(st.pattern)));
            json_object_set_new(o, "face_orders", json_integer(view == ORI_RENDER_3D ? st.face_order_count : 0));
            json_object_set_new(o, "failing_vertices", failing >= 0 ? json_integer(failing) : json_null());
            json_object_set_new(o, "color", color != CLI_COLOR_NONE ? cli_colors_json(&colors) : json_null());
            cli_print_json(o);
        } else {
            printf("wrote %s: %s of %s, %s (%dx%d %s)", out, view_name, sa.path, st.label, def.width, def.height,
                   ori_image_format_name(format));
            if (failing > 0)
                printf("; %d %s not locally flat-foldable %s ringed", failing, failing == 1 ? "vertex" : "vertices",
                       failing == 1 ? "is" : "are");
            if (color != CLI_COLOR_NONE)
                printf("; %s of %d %s from %.4g to %.4g", cli_color_name(color), colors.shown,
                       colors.face_values ? "faces" : "creases", colors.min, colors.max);
            printf("\n");
        }
    }
    ori_buffer_free(texture);
    cli_colors_free(&colors);
    cli_state_free(&st);
    return rc;
}

const cli_command cli_cmd_render = {
    "render",
    "a picture of any state: the crease pattern or the folded sheet in 3D (SVG, PDF, PNG)",
    "usage: orikin render IN [--frame N | fold options | --at T] [--view cp|3d]\n"
    "                     [--camera iso|top|front|side|bottom] [--yaw DEG] [--pitch DEG]\n"
    "                     [--roll DEG] [--perspective] [--size WxH] [--front COLOR] [--back COLOR]\n"
    "                     [--texture IMG.png] [--edges] [--grid] [--labels]\n"
    "                     [--color strain|fold-angle|target-error] [--json]\n"
    "                     -o OUT.{svg,pdf,png}\n"
    "\n"
    "Draw a state of IN. IN is a FOLD file (--frame N: a folded form, or a crease pattern posed\n"
    "from its edges_foldAngle; or a fold given by the options of `orikin fold`, whose last step\n"
    "is drawn), a drawing (.svg, .opx, .cp: its crease pattern) or a fold sequence SEQ.json\n"
    "(--at T: the instant T, default its end). The crease\n"
    "view (cp) draws the flat pattern as the thesis does: mountains red dash-dot, valleys blue\n"
    "dashed, boundary black, flat creases grey, unassigned purple dots, cuts green, joins light\n"
    "grey; vertices that are not locally flat-foldable are ringed in orange. The 3D view draws\n"
    "the posed sheet with two colours (front = the side facing +z in the flat sheet),\n"
    "directional light and the creases on top; SVG and PDF are true vector drawings, faces\n"
    "sorted back to front (cycles split); faces folded flat onto each other follow the frame's\n"
    "faceOrders when it has them (a folded form's own, or the frame `orikin layers -o` writes),\n"
    "else the fold tree. The view is cp for a crease-pattern frame (unless a\n"
    "3D option is given), 3D for a folded form, a fold or a sequence.\n"
    "--color paints a quantity in either view with a colour bar on the right (viridis from the\n"
    "smallest value shown to the largest, five labelled ticks): strain per face (the largest\n"
    "|axial strain| of its bars, from the frames `orikin fold --compliant -o` writes), fold-angle\n"
    "or target-error (|angle - target x orikin:fraction|) per crease; painted faces are not shaded.\n"
    "\n",
    run,
    "options:\n"
    "  --frame N            the state in frame N of a FOLD file (default 0)\n"
    "  --fix F --drive E --to DEG [--from DEG] [--step DEG] [--lock E1,...] [--solver S]\n"
    "  [--linear L]         a fold (see orikin fold); the state is its last step. F: a face index,\n"
    "                       name (Obj12) or @x,y; E: a crease index or @x,y; --lock 3,@0.5,1,9\n"
    CLI_STATE_MODES_HELP
    "  --at T               the instant T of a fold sequence (default: its end)\n"
    "  --view cp|3d         the crease pattern or the posed sheet\n"
    "  --camera PRESET      iso (default), top, front, side or bottom\n"
    "  --yaw DEG            turn the model about the vertical axis (counter-clockwise from above)\n"
    "  --pitch DEG          tilt the view: the top comes towards the viewer\n"
    "  --roll DEG           turn the image counter-clockwise\n"
    "  --perspective        perspective projection (default orthographic)\n"
    "  --size WxH           image size in pixels (PNG) or points (SVG, PDF); default 800x600,\n"
    "                       at most 16384x16384\n"
    "  --front COLOR        colour of the front side: #rrggbb, #rgb or a name (default #e8a33d)\n"
    "  --back COLOR         colour of the back side (default #f3efe4)\n"
    "  --texture IMG.png    an image on the front side, stretched over the flat sheet\n"
    "  --edges              also draw flat (F) creases and joins (J) in 3D\n"
    "  --grid               a ground grid under the sheet\n"
    "  --labels             vertex, edge and face indices (crease view)\n"
    CLI_COLOR_HELP
    "  --json               print {output, format, view, width, height, state, faces,\n"
    "                       face_orders, failing_vertices, color {quantity, per, shown, min,\n"
    "                       max, labels} | null}\n"
    "  -o OUT               the picture; its format by the suffix .svg, .pdf or .png\n"
    "\n"
    "example: orikin render examples/open-corner.seq.json --yaw 90 -o corner-cube.png\n"
    "         orikin render bent.fold --frame 1 --color strain -o strain.png\n",
};
