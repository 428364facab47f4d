// orikin export: the posed sheet of any state as a mesh (OBJ, STL, PLY, glTF, GLB), two-sided
// or thickened into a closed solid, or the whole motion as a glTF animation.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "color_args.h"
#include "state_args.h"

static int run(int argc, char **argv)
{
    const char *cmd = "export";
    cli_state_args sa;
    cli_state_args_init(&sa);
    const char *out = NULL;
    bool json = false, animate = false, has_thickness = false, has_front = false, has_back = false;
    double thickness = 0.0;
    int color = -1; // --color: -1 not given (strain when the frame has strains), 0 none, 1 strain
    ori_export_def def = ori_default_export_def();
    int rc;
    for (int i = 1; i < argc; ++i) {
        int took = cli_state_option(cmd, argc, argv, &i, &sa, &rc);
        if (took < 0) return rc;
        if (took) continue;
        const char *o = argv[i];
        if (strcmp(o, "-o") == 0) {
            if (out) return cli_usage(cmd, "-o given twice");
            if (!(out = cli_option_value(cmd, argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(o, "--thickness") == 0) {
            if (has_thickness) return cli_usage(cmd, "--thickness given twice");
            const char *v = cli_option_value(cmd, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &thickness) || thickness < 0.0)
                return cli_usage(cmd, "--thickness needs a length >= 0 (pattern units), got '%s'", v);
            has_thickness = true;
        } else if (strcmp(o, "--front") == 0 || strcmp(o, "--back") == 0) {
            bool front = o[2] == 'f';
            if (front ? has_front : has_back) return cli_usage(cmd, "%s given twice", o);
            const char *v = cli_option_value(cmd, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!ori_rgb_parse(v, front ? &def.front : &def.back))
                return cli_usage(cmd, "%s needs a colour (#rrggbb, #rgb or a name such as orange), got '%s'", o, v);
            *(front ? &has_front : &has_back) = true;
        } else if (strcmp(o, "--color") == 0) {
            if (color >= 0) return cli_usage(cmd, "--color given twice");
            const char *v = cli_option_value(cmd, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (strcmp(v, "strain") == 0) color = 1;
            else if (strcmp(v, "none") == 0) color = 0;
            else return cli_usage(cmd, "--color is strain or none (a mesh colours its faces by strain), got '%s'", v);
        } else if (strcmp(o, "--animate") == 0) {
            if (animate) return cli_usage(cmd, "--animate given twice");
            animate = true;
        } else if (strcmp(o, "--json") == 0) {
            json = true;
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage(cmd, "unknown option %s", o);
        } else {
            return cli_usage(cmd, "one IN only");
        }
    }
    if ((rc = cli_state_finish(cmd, &sa)) != CLI_EXIT_OK) return rc;
    if (!out) return cli_usage(cmd, "missing -o OUT.obj, OUT.stl, OUT.ply, OUT.gltf or OUT.glb");
    ori_mesh_format format = ori_mesh_format_from_path(out);
    if (format == ORI_MESH_UNKNOWN)
        return cli_usage(cmd, "-o %s: unknown mesh format (use .obj, .stl, .ply, .gltf or .glb)", out);
    if (animate) {
        if (format != ORI_MESH_GLTF && format != ORI_MESH_GLB)
            return cli_usage(cmd, "--animate writes a glTF animation: use -o OUT.gltf or OUT.glb");
        if (thickness > 0.0) return cli_usage(cmd, "--animate moves each face as a rigid node: it takes no --thickness");
        if (sa.has_at) return cli_usage(cmd, "--animate exports the whole sequence: --at picks one instant");
        if (sa.source == CLI_STATE_FRAME && sa.has_frame)
            return cli_usage(cmd, "--animate exports every frame of IN: --frame only starts a fold given with fold options");
    }
    bool gltf = format == ORI_MESH_GLTF || format == ORI_MESH_GLB;
    if (color == 1 && !gltf) return cli_usage(cmd, "--color strain writes vertex colours (COLOR_0): use -o OUT.gltf or OUT.glb");
    if (color == 1 && animate) return cli_usage(cmd, "--color strain colours one state: it takes no --animate");
    cli_state st;
    if ((rc = cli_state_load(cmd, &sa, !animate, &st)) != CLI_EXIT_OK) return rc;
    // Strain colours: asked for, or by default for a glTF of a frame that carries strains.
    cli_colors colors;
    memset(&colors, 0, sizeof colors);
    bool colored = color == 1;
    if (color < 0 && gltf && !animate && st.compliant) colored = true; // (as a compliant fold's frame carries them)
    if (color < 0 && gltf && !animate && st.source == CLI_STATE_FRAME && st.doc) {
        const char *keys[2] = {"faces_orikin:strain", "edges_orikin:strain"};
        for (int k = 0; k < 2 && !colored; ++k) {
            char *t = ori_fold_get_custom(st.doc, sa.frame, keys[k]);
            colored = t != NULL;
            ori_buffer_free(t);
        }
    }
    if (colored && (rc = cli_colors_load(cmd, &sa, &st, CLI_COLOR_STRAIN, &colors)) != CLI_EXIT_OK) {
        cli_state_free(&st);
        return rc;
    }
    if (colored) def.values = cli_colors_map(&colors);
    ori_state_view sv = cli_state_view(&st);
    ori_mesh *mesh = NULL;
    ori_error err;
    if (ori_mesh_create(&sv, &mesh, &err) != ORI_OK) {
        cli_colors_free(&colors);
        cli_state_free(&st);
        return cli_input_error(cmd, sa.path, &err);
    }
    cli_motion m;
    memset(&m, 0, sizeof m);
    ori_rigid *poses = NULL;
    if (animate) {
        if ((rc = cli_state_motion(cmd, &st, 0, &m)) != CLI_EXIT_OK) goto done;
        poses = m.poses;
        bool bends = st.compliant != NULL; // (its faces bend: no rigid face nodes)
        if (!poses && !bends) {
            // A FOLD file without a crease pattern to fit against: each face's rigid motion from
            // its position in the first frame; where a face is not rigid, the mesh morphs.
            poses = malloc(sizeof(ori_rigid) * (size_t)m.count * (size_t)m.face_count + 1);
            for (int k = 0; k < m.count && !bends; ++k)
                for (int f = 0; f < m.face_count && !bends; ++f)
                    bends = ori_mesh_face_pose(mesh, f, m.positions + (size_t)k * m.vertex_count,
                                               &poses[(size_t)k * m.face_count + f], &err) != ORI_OK;
        }
        def.keyframe_count = m.count;
        def.keyframe_times_s = m.times;
        if (bends) {
            // One mesh posed as the first keyframe, morphing to each of the others
            if (poses != m.poses) free(poses);
            poses = NULL;
            ori_mesh_destroy(mesh);
            mesh = NULL;
            ori_state_view first = {sv.pattern, m.positions, m.angles ? m.angles : sv.fold_angles_rad};
            if (ori_mesh_create(&first, &mesh, &err) != ORI_OK) {
                rc = cli_input_error(cmd, sa.path, &err);
                goto done;
            }
            def.keyframe_positions = m.positions;
        } else {
            def.keyframe_poses = poses;
        }
    }
    def.format = format;
    def.thickness = thickness;
    def.face_orders = st.face_orders; // the frame's layer order ranks the panels stacked flat
    def.face_order_count = st.face_order_count;
    ori_thick_info thick;
    memset(&thick, 0, sizeof thick);
    ori_status s = thickness > 0.0 ? ori_mesh_thick_panels(mesh, &def, &thick, &err) : ORI_OK;
    if (s == ORI_OK) s = ori_mesh_export_file(mesh, &def, out, &err);
    if (s != ORI_OK) {
        rc = cli_input_error(cmd, s == ORI_ERR_IO ? out : sa.path, &err);
        goto done;
    }
    double area = ori_mesh_area(mesh);
    if (json) {
        json_t *o = json_object();
        json_object_set_new(o, "output", json_string(out));
        json_object_set_new(o, "format", json_string(ori_mesh_format_name(format)));
        json_object_set_new(o, "state", json_string(animate ? "motion" : st.label));
        json_object_set_new(o, "vertices", json_integer(ori_mesh_vertex_count(mesh)));
        json_object_set_new(o, "faces", json_integer(ori_mesh_face_count(mesh)));
        json_object_set_new(o, "triangles", json_integer(ori_mesh_triangle_count(mesh)));
        json_object_set_new(o, "area", json_real(area));
        json_object_set_new(o, "thickness", json_real(thickness));
        json_object_set_new(o, "volume", thickness > 0.0 ? json_real(area * thickness) : json_null());
        json_object_set_new(o, "panels", thickness > 0.0 ? json_integer(thick.panels) : json_null());
        json_object_set_new(o, "stacked_panels", thickness > 0.0 ? json_integer(thick.stacked) : json_null());
        json_object_set_new(o, "front_panels", thickness > 0.0 ? json_integer(thick.front) : json_null());
        json_object_set_new(o, "overlapping", thickness > 0.0 ? json_integer(thick.overlapping) : json_null());
        json_object_set_new(o, "keyframes", json_integer(animate ? m.count : 0));
        json_object_set_new(o, "morph", json_boolean(def.keyframe_positions != NULL));
        json_object_set_new(o, "duration_s", animate ? json_real(m.times[m.count - 1] - m.times[0]) : json_null());
        json_object_set_new(o, "color", colored ? cli_colors_json(&colors) : json_null());
        cli_print_json(o);
    } else if (animate && def.keyframe_positions) {
        printf("wrote %s: one mesh of %d faces morphing through %d keyframes over %g s (the faces bend) (%s)\n", out,
               ori_mesh_face_count(mesh), m.count, m.times[m.count - 1] - m.times[0], ori_mesh_format_name(format));
    } else if (animate) {
        printf("wrote %s: %d faces as nodes, %d keyframes over %g s (%s)\n", out, ori_mesh_face_count(mesh), m.count,
               m.times[m.count - 1] - m.times[0], ori_mesh_format_name(format));
    } else {
        printf("wrote %s: %s of %s, %d triangles per side, area %.10g", out, st.label, sa.path, ori_mesh_triangle_count(mesh),
               area);
        if (thickness > 0.0) {
            printf(", %d closed offset panel solids %g thick, volume %.10g", thick.panels, thickness, area * thickness);
            if (thick.stacked) printf(", %d panels stacked flat, lifted by their layer", thick.stacked);
            if (thick.front) printf(", %d on the front side", thick.front);
            if (thick.overlapping) printf(", %d triangle pairs still overlapping", thick.overlapping);
        }
        if (colored) printf(", COLOR_0 by strain from %.4g to %.4g", colors.min, colors.max);
        printf(" (%s)\n", ori_mesh_format_name(format));
        if (format == ORI_MESH_OBJ) printf("wrote its materials (front, back%s) beside it, .mtl\n", thickness > 0.0 ? ", rim" : "");
    }
done:
    if (poses && poses != m.poses) free(poses);
    cli_motion_free(&m);
    ori_mesh_destroy(mesh);
    cli_colors_free(&colors);
    cli_state_free(&st);
    return rc;
}

const cli_command cli_cmd_export = {
    "export",
    "a mesh of any state (OBJ, STL, PLY, glTF, GLB), thickened or animated",
    "usage: orikin export IN [--frame N | fold options | --at T] [--thickness T] [--animate]\n"
    "                     [--front COLOR] [--back COLOR] [--color strain|none] [--json]\n"
    "                     -o OUT.{obj,stl,ply,gltf,glb}\n"
    "\n"
    "Write the posed sheet of a state of IN (see orikin render for the state options) as a mesh:\n"
    "every face triangulated (ear clipping, non-convex faces too), both sides with their normals\n"
    "(front = the side facing +z in the flat sheet) and materials, the FOLD indices kept (OBJ\n"
    "vertex i = FOLD vertex i-1; PLY properties fold_vertex and fold_face; glTF extras).\n"
    "Coordinates are exact: the text formats write the shortest decimal that reads back to the\n"
    "posed double, glTF adds the attribute _POSITION_LO to its 32-bit POSITION. --thickness T\n"
    "writes separate closed offset panel solids (one per flat region, on the back side of the\n"
    "sheet so that valley hinges lie on the front surface, or on its front where the back would\n"
    "overlap; panels stacked flat at +-180 deg are lifted by their layer, from faceOrders or the\n"
    "fold tree, so they do not interpenetrate; --json counts what was done and what overlaps;\n"
    "every edge of a panel shared by two of its triangles; volume = area x T), for 3D printing;\n"
    "the file names them (OBJ objects panel_K, STL solids orikin_thick_panel_K). --animate\n"
    "writes the whole motion (a fold's steps, a sequence's recorded states, or a FOLD file's\n"
    "frames) as a glTF animation: one node per face, rotation and translation keyframes from the\n"
    "exact face poses, one second per fold; faces that bend (--compliant, or frames that are not\n"
    "rigid) make one mesh morphing through the states. A glTF of a frame that carries strains\n"
    "(the frames `orikin fold --compliant -o` writes) gets every vertex coloured by its face's strain\n"
    "(COLOR_0, viridis from the smallest to the largest, as render --color strain; white materials).\n"
    "\n",
    run,
    "options:\n"
    "  --frame N            the state in frame N of a FOLD file (default 0)\n"
    "  --fix F --drive E --to DEG [--from DEG] [--step DEG] [--lock E1,...] [--solver S]\n"
    "  [--linear L]         a fold (see orikin fold); its last step, or with --animate every step.\n"
    "                       F: a face index, name (Obj12) or @x,y; E: a crease index or @x,y;\n"
    "                       --lock 3,@0.5,1,9\n"
    CLI_STATE_MODES_HELP
    "  --at T               the instant T of a fold sequence (default: its end)\n"
    "  --thickness T        a closed solid T thick (pattern units); 0 = a two-sided sheet\n"
    "  --animate            the whole motion as a glTF animation (.gltf or .glb only)\n"
    "  --front COLOR        material of the front side (default #e8a33d)\n"
    "  --back COLOR         material of the back side (default #f3efe4)\n"
    "  --color strain|none  glTF/GLB vertex colours by face strain (default: strain when the\n"
    "                       frame has faces_orikin:strain or edges_orikin:strain), or none\n"
    "  --json               print {output, format, state, vertices, faces, triangles, area,\n"
    "                       thickness, volume, panels, stacked_panels, front_panels,\n"
    "                       overlapping, keyframes, duration_s, color {quantity, per, shown,\n"
    "                       min, max, labels} | null}\n"
    "  -o OUT               the mesh; its format by the suffix .obj, .stl, .ply, .gltf or .glb\n"
    "                       (an OBJ comes with its materials in OUT.mtl beside it)\n"
    "\n"
    "example: orikin export examples/open-corner.seq.json --animate -o open-corner.glb\n",
};
