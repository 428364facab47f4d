// orikin fab: the fabrication files of a crease pattern: a GDSII lithography mask (with its layer
// map), a DXF or a laser-cutter SVG, by the output's extension.
#include <math.h>
#include <string.h>

#include "fab_args.h"
#include "kin_args.h"

typedef enum out_kind { OUT_GDS, OUT_DXF, OUT_SVG } out_kind;

static bool ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    if (n < m) return false;
    for (size_t i = 0; i < m; ++i) {
        char c = s[n - m + i];
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != suffix[i]) return false;
    }
    return true;
}

// Lengths given on the command line (value and unit as parsed; has = given).
typedef struct len_opt {
    const char *name;
    bool has;
    double value, unit_m;
} len_opt;

enum { L_GAP, L_HINGE_WIDTH, L_OVERLAP, L_WIRE_WIDTH, L_PAD, L_LEAD, L_MARK, L_MARK_MARGIN, L_LABEL_HEIGHT, L_DBU,
       L_DASH, L_DASH_GAP, L_VERTEX_GAP, L_SLIT, L_PITCH, L_STROKE, L_COUNT };
static const char *const len_names[L_COUNT] = {"--gap", "--hinge-width", "--overlap", "--wire-width", "--pad",
                                               "--lead", "--mark", "--mark-margin", "--label-height", "--dbu",
                                               "--dash", "--dash-gap", "--vertex-gap", "--slit", "--pitch", "--stroke"};

static json_t *shapes_json(const ori_fab_layout *l, double scale)
{
    json_t *a = json_array();
    for (int i = 0; i < ori_fab_shape_count(l); ++i) {
        ori_fab_shape s = ori_fab_shape_at(l, i);
        json_t *o = json_object(), *pts = json_array();
        json_object_set_new(o, "layer", json_integer(s.layer));
        json_object_set_new(o, "kind", json_string(s.kind == ORI_FAB_POLYGON ? "polygon" : s.kind == ORI_FAB_PATH ? "path" : "text"));
        json_object_set_new(o, "element", s.element >= 0 ? json_integer(s.element) : json_null());
        for (int k = 0; k < s.point_count; ++k)
            json_array_append_new(pts, json_pack("[II]", (json_int_t)nearbyint(s.points[k].x * scale),
                                                 (json_int_t)nearbyint(s.points[k].y * scale)));
        json_object_set_new(o, "points", pts);
        if (s.kind == ORI_FAB_PATH) json_object_set_new(o, "width", json_integer((json_int_t)nearbyint(s.width * scale)));
        if (s.text) json_object_set_new(o, "text", json_string(s.text));
        json_array_append_new(a, o);
    }
    return a;
}

static char *map_path(const char *out)
{
    size_t n = strlen(out);
    char *p = malloc(n + 5);
    memcpy(p, out, n + 1);
    if (ends_with(p, ".gds")) p[n - 4] = '\0';
    strcat(p, ".map");
    return p;
}

static int run(int argc, char **argv)
{
    const char *cmd = "fab", *path = NULL, *out = NULL, *v, *unit = NULL, *fix = NULL, *label = NULL, *materials = NULL;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    bool json = false, perforate = false, has_scale = false;
    double scale_mm = 1.0;
    len_opt len[L_COUNT];
    for (int k = 0; k < L_COUNT; ++k) len[k] = (len_opt){len_names[k], false, 0.0, 0.0};
    for (int i = 1; i < argc; ++i) {
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        int lk = -1;
        for (int k = 0; k < L_COUNT; ++k)
            if (strcmp(argv[i], len_names[k]) == 0) lk = k;
        if (lk >= 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!fab_parse_length(v, &len[lk].value, &len[lk].unit_m))
                return cli_usage(cmd, "%s: a length >= 0, bare or with a unit (20, 20um, 0.5mm), not \"%s\"", len_names[lk], v);
            len[lk].has = true;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--unit") == 0) {
            if (!(unit = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--fix") == 0) {
            if (!(fix = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--label") == 0) {
            if (!(label = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (strlen(label) >= ORI_FAB_LABEL_MAX) return cli_usage(cmd, "--label: at most %d bytes", ORI_FAB_LABEL_MAX - 1);
        } else if (strcmp(argv[i], "--materials") == 0) {
            if (!(materials = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--scale") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &scale_mm) || !(scale_mm > 0.0))
                return cli_usage(cmd, "--scale: millimetres per pattern unit, a number > 0, not \"%s\"", v);
            has_scale = true;
        } else if (strcmp(argv[i], "--perforate") == 0) {
            perforate = true;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_usage(cmd, "unknown option %s", argv[i]);
        } else if (path) {
            return cli_usage(cmd, "one FILE only (got %s and %s)", path, argv[i]);
        } else {
            path = argv[i];
        }
    }
    if (!path) return cli_usage(cmd, "FILE is missing");
    if (!out || cli_is_stdout(out)) return cli_usage(cmd, "-o OUT.gds, OUT.dxf or OUT.svg is required (binary output is not for stdout)");
    out_kind kind;
    if (ends_with(out, ".gds")) kind = OUT_GDS;
    else if (ends_with(out, ".dxf")) kind = OUT_DXF;
    else if (ends_with(out, ".svg")) kind = OUT_SVG;
    else return cli_usage(cmd, "-o %s: the extension says the format: .gds, .dxf or .svg", out);
    double unit_m = 0.0;
    if (unit) {
        ori_error e;
        if (ori_unit_meters(unit, &unit_m, &e) != ORI_OK) return cli_usage(cmd, "--unit: %s", e.message);
    }
    if (kind == OUT_GDS) {
        for (int k = L_DASH; k <= L_STROKE; ++k)
            if (len[k].has) return cli_usage(cmd, "%s: a cutting-file option (-o .dxf or .svg)", len_names[k]);
        if (perforate || has_scale) return cli_usage(cmd, "%s: a cutting-file option (-o .dxf or .svg)", perforate ? "--perforate" : "--scale");
    } else {
        for (int k = L_GAP; k <= L_DBU; ++k)
            if (len[k].has) return cli_usage(cmd, "%s: a mask option (-o .gds)", len_names[k]);
        if (fix || label || materials) return cli_usage(cmd, "%s: a mask option (-o .gds)", fix ? "--fix" : label ? "--label" : "--materials");
        if (kind == OUT_DXF && (perforate || len[L_DASH].has || len[L_DASH_GAP].has || len[L_VERTEX_GAP].has ||
                                len[L_SLIT].has || len[L_PITCH].has || len[L_STROKE].has))
            return cli_usage(cmd, "the dash and perforation options are for -o .svg (a DXF has whole lines)");
    }

    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    int rc = cli_input_load(cmd, path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p)) {
        rc = cli_input_fail(cmd, path, "frame %d is folded: fab needs the flat crease pattern (frame 0)", in.frame);
        goto done;
    }
    double file_m = 0.0;
    bool has_file_unit = fab_file_unit(doc, &file_m);
    double mpu = unit ? unit_m : has_file_unit ? file_m : 0.0;
    json_t *summary = json_object();
    json_object_set_new(summary, "file", json_string(path));
    json_object_set_new(summary, "output", json_string(out));
    ori_error err;
    if (kind == OUT_GDS) {
        if (!(mpu > 0.0)) {
            json_decref(summary);
            rc = cli_input_fail(cmd, path, "frame_unit: the coordinates are unitless (--unit U: m, cm, mm, um, nm, in, pt)");
            goto done;
        }
        ori_materials *mat = ori_materials_create();
        ori_design *design = NULL;
        ori_fab_layout *l = NULL;
        unsigned char *bytes = NULL;
        char *map = NULL, *mpath = NULL;
        if (materials && ori_materials_load_file(mat, materials, &err) != ORI_OK) rc = cli_input_error(cmd, materials, &err);
        ori_design_def dd = ori_default_design_def();
        dd.doc = doc;
        dd.pattern = p;
        dd.materials = mat;
        dd.has_meters_per_unit = true;
        dd.meters_per_unit = mpu;
        if (rc == CLI_EXIT_OK && ori_design_create(&dd, &design, &err) != ORI_OK) rc = cli_input_error(cmd, path, &err);
        ori_fab_def fd = ori_default_fab_def();
        fd.pattern = p;
        fd.design = design;
        fd.meters_per_unit = mpu;
        if (rc == CLI_EXIT_OK && fix) rc = cli_spec_face(cmd, path, p, "--fix", fix, &fd.fixed_face);
        double *fields[] = {&fd.hinge_gap_m, &fd.hinge_width_m, &fd.hinge_overlap_m, &fd.wire_width_m, &fd.pad_size_m,
                            &fd.lead_length_m, &fd.mark_size_m, &fd.mark_margin_m, &fd.label_height_m};
        for (int k = L_GAP; k <= L_LABEL_HEIGHT; ++k)
            if (len[k].has) *fields[k] = fab_length_m(len[k].value, len[k].unit_m, mpu);
        if (len[L_GAP].has && !(fd.hinge_gap_m > 0.0)) rc = cli_usage(cmd, "--gap: the hinge gap must be > 0");
        if (label) snprintf(fd.label, sizeof fd.label, "%s", label);
        ori_gds_def gd = ori_default_gds_def();
        if (len[L_DBU].has) {
            gd.database_unit_m = fab_length_m(len[L_DBU].value, len[L_DBU].unit_m, mpu);
            if (!(gd.database_unit_m > 0.0)) rc = cli_usage(cmd, "--dbu: the database unit must be > 0");
        }
        if (rc == CLI_EXIT_OK && ori_fab_layout_create(&fd, &l, &err) != ORI_OK) rc = cli_input_error(cmd, path, &err);
        size_t size = 0;
        if (rc == CLI_EXIT_OK && !(bytes = ori_gds_write(l, &gd, &size, &err))) rc = cli_input_error(cmd, path, &err);
        if (rc == CLI_EXIT_OK) {
            map = ori_fab_layer_map(l);
            mpath = map_path(out);
            if (ori_file_write_atomic(out, bytes, size, &err) != ORI_OK) rc = cli_input_error(cmd, out, &err);
            else if (ori_file_write_atomic(mpath, map, strlen(map), &err) != ORI_OK) rc = cli_input_error(cmd, mpath, &err);
        }
        if (rc == CLI_EXIT_OK) {
            int counts[ORI_FAB_LAYER_LAST + 1] = {0};
            for (int i = 0; i < ori_fab_shape_count(l); ++i) counts[ori_fab_shape_at(l, i).layer]++;
            double dbu = gd.database_unit_m > 0.0 ? gd.database_unit_m : mpu / 1000.0;
            json_object_set_new(summary, "format", json_string("gds"));
            json_object_set_new(summary, "layer_map", json_string(mpath));
            json_object_set_new(summary, "bytes", json_integer((json_int_t)size));
            json_object_set_new(summary, "meters_per_unit", json_real(mpu));
            json_object_set_new(summary, "database_unit", json_real(dbu));
            json_t *layers = json_array();
            for (int k = ORI_FAB_LAYER_FIRST; k <= ORI_FAB_LAYER_LAST; ++k)
                json_array_append_new(layers, json_pack("{s:i,s:s,s:i}", "layer", k, "name", ori_fab_layer_name(k), "shapes", counts[k]));
            json_object_set_new(summary, "layers", layers);
            if (json) json_object_set_new(summary, "shapes", shapes_json(l, mpu / dbu));
            cli_print_summary(json, summary, "%s: %d panels, %d hinges, %d wires, %d pads, %d marks (layers in %s), "
                                             "database unit %g m",
                              out, counts[ORI_FAB_PANEL], counts[ORI_FAB_HINGE], counts[ORI_FAB_WIRE], counts[ORI_FAB_PAD],
                              counts[ORI_FAB_MARK] / 2, mpath, dbu);
        } else {
            json_decref(summary);
        }
        free(mpath);
        ori_buffer_free(map);
        ori_buffer_free(bytes);
        ori_fab_layout_destroy(l);
        ori_design_destroy(design);
        ori_materials_destroy(mat);
        goto done;
    }
    ori_cut_def cd = ori_default_cut_def();
    cd.mm_per_unit = has_scale ? scale_mm : mpu > 0.0 ? mpu * 1e3 : 1.0;
    cd.perforate = perforate;
    double *cfields[] = {&cd.dash_mm, &cd.gap_mm, &cd.vertex_gap_mm, &cd.perforation_mm, &cd.perforation_pitch_mm, &cd.stroke_mm};
    for (int k = L_DASH; k <= L_STROKE; ++k)
        if (len[k].has) *cfields[k - L_DASH] = len[k].unit_m > 0.0 ? len[k].value * len[k].unit_m * 1e3 : len[k].value;
    if (!(cd.dash_mm > 0.0) || !(cd.perforation_mm > 0.0) || !(cd.stroke_mm > 0.0)) {
        json_decref(summary);
        rc = cli_usage(cmd, "--dash, --slit and --stroke must be > 0");
        goto done;
    }
    if (perforate && !(cd.perforation_pitch_mm > cd.perforation_mm)) {
        json_decref(summary);
        rc = cli_usage(cmd, "--pitch must be longer than --slit (a slit starts every pitch)");
        goto done;
    }
    char *text = kind == OUT_DXF ? ori_dxf_write(p, &cd, &err) : ori_cut_svg_write(p, &cd, &err);
    if (!text) {
        rc = cli_input_error(cmd, path, &err);
        json_decref(summary);
    } else if (ori_file_write_atomic(out, text, strlen(text), &err) != ORI_OK) {
        rc = cli_input_error(cmd, out, &err);
        json_decref(summary);
    } else {
        int n[4] = {0};
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_assignment a = ori_pattern_edge(p, e).assignment;
            if (a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT) n[0]++;
            else if (a == ORI_ASSIGN_MOUNTAIN) n[1]++;
            else if (a == ORI_ASSIGN_VALLEY) n[2]++;
            else if (a == ORI_ASSIGN_UNASSIGNED) n[3]++;
        }
        json_object_set_new(summary, "format", json_string(kind == OUT_DXF ? "dxf" : "svg"));
        json_object_set_new(summary, "mm_per_unit", json_real(cd.mm_per_unit));
        json_object_set_new(summary, "cut", json_integer(n[0]));
        json_object_set_new(summary, "mountain", json_integer(n[1]));
        json_object_set_new(summary, "valley", json_integer(n[2]));
        json_object_set_new(summary, "unassigned", json_integer(n[3]));
        if (kind == OUT_SVG) {
            json_object_set_new(summary, "crease_style", json_string(perforate ? "perforated" : "dashed"));
            json_object_set_new(summary, "dash_mm", json_real(perforate ? cd.perforation_mm : cd.dash_mm));
            json_object_set_new(summary, "gap_mm", json_real(perforate ? cd.perforation_pitch_mm - cd.perforation_mm : cd.gap_mm));
            json_object_set_new(summary, "vertex_gap_mm", json_real(cd.vertex_gap_mm));
        }
        cli_print_summary(json, summary, "%s: %d cut, %d mountain, %d valley, %d unassigned lines, %g mm per unit", out, n[0],
                          n[1], n[2], n[3], cd.mm_per_unit);
    }
    ori_buffer_free(text);
done:
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return cli_finish(rc);
}

const cli_command cli_cmd_fab = {
    "fab",
    "fabrication files: a GDSII lithography mask (panels, hinges, wires, marks), DXF or laser SVG",
    "usage: orikin fab FILE -o OUT.gds [mask options]\n"
    "       orikin fab FILE -o OUT.dxf|OUT.svg [cutting options]\n"
    "\n"
    "Write the fabrication files of a flat crease pattern; the extension of OUT says which.\n"
    "OUT.gds is a GDSII stream of one cell DEVICE: the panels (each face, its creases moved\n"
    "inward by half the hinge gap) on layer 1, hinge metal strips on 2 (the width along the\n"
    "crease and the gap, the span, from edges_orikin:hinge; orikin actuate sizes them), the\n"
    "actuation wires on 3 (paths: the loop on the moving panel at its lever, leads across the\n"
    "crease) with their pads on 4, alignment crosses on 5 and a text label on 6; OUT.map beside\n"
    "it lists the layers. The user unit is FILE's frame_unit, the database unit a thousandth of\n"
    "it (nm for um). OUT.dxf is an ASCII DXF R12 in mm with the layers CUT (B, C), MOUNTAIN,\n"
    "VALLEY and UNASSIGNED; OUT.svg a laser-cutter SVG in mm: cuts solid black, mountain creases\n"
    "red and valley creases blue on their own layers, each crease as dashes that stop short of\n"
    "its vertices, or with --perforate as cut-through slits. F and J edges are not written.\n"
    "Lengths are bare numbers (mask: pattern units; cutting: mm) or carry a unit (20um, 0.5mm).\n"
    "docs/fabrication.md has the layers and conventions.\n"
    "\n"
    "mask options (-o .gds):\n"
    "  --unit U           length unit of the coordinates when FILE has none: m, cm, mm, um, nm,\n"
    "                     in, pt\n"
    "  --fix FACE         the face held while folding: a wire goes on the other side of its\n"
    "                     crease (default the face at the sheet's centre)\n"
    "  --gap LEN          gap between the panels across every crease (default each hinge's span;\n"
    "                     20 um without hinge data)\n"
    "  --hinge-width LEN  every hinge strip this wide along its crease (default the design's; the\n"
    "                     crease less the gap without hinge data)\n"
    "  --overlap LEN      how far a hinge strip reaches onto each panel (default 10 um)\n"
    "  --wire-width LEN   every wire's trace width (default the wire's, or its hinge's, width)\n"
    "  --pad LEN          pad side (default 100 um)\n"
    "  --lead LEN         lead length from the crease to its pad (default 150 um)\n"
    "  --mark LEN         alignment cross size (default 100 um; 0: none)\n"
    "  --mark-margin LEN  distance of the crosses from the sheet (default 200 um)\n"
    "  --label TEXT       text on layer 6 (default \"orikin\")\n"
    "  --label-height LEN its height (default 100 um; 0: no label)\n"
    "  --dbu LEN          database unit (default a thousandth of the user unit)\n"
    "  --materials FILE   materials JSON for the hinge data (as for orikin actuate)\n"
    "cutting options (-o .dxf, .svg):\n"
    "  --scale MM         millimetres per pattern unit (default from frame_unit; 1 when unitless)\n"
    "  --dash LEN         SVG: dash length (default 3 mm)\n"
    "  --dash-gap LEN     SVG: gap between dashes (default 1.5 mm)\n"
    "  --vertex-gap LEN   SVG: the dashes stop this far from each vertex (default 1 mm)\n"
    "  --perforate        SVG: creases as cut-through slits instead of dashes\n"
    "  --slit LEN         SVG: slit length (default 0.5 mm)\n"
    "  --pitch LEN        SVG: slit start to slit start (default 1.5 mm)\n"
    "  --stroke LEN       SVG: line width (default 0.1 mm)\n",
    run,
    "options:\n"
    CLI_INPUT_HELP
    "  --json             print {file, output, format, ...}: for a mask layer_map, bytes,\n"
    "                     meters_per_unit, database_unit, layers: [{layer, name, shapes}], shapes:\n"
    "                     [{layer, kind, element, points (database units), width, text}]; for a\n"
    "                     cutting file mm_per_unit, cut, mountain, valley, unassigned and (SVG)\n"
    "                     crease_style, dash_mm, gap_mm, vertex_gap_mm\n"
    "\n"
    "example: orikin fab examples/patterns/open-corner-gold.fold -o corner.gds\n",
};
