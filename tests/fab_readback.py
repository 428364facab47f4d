#!/usr/bin/env python3
"""Round trips of `orikin fab` through independent readers from Debian (docs/fabrication.md).

usage: fab_readback.py ORIKIN SOURCE_DIR

- GDSII: gdspy (python3-gdspy) reads the mask back; per layer the polygons, the paths (spine and
  width) and the text are identical to the layout the CLI reports (--json, database units):
  0 differences at the database unit. The panels are the FOLD file's faces, each inside its face.
- DXF: ezdxf (python3-ezdxf) audits it with 0 errors; its LINE entities per layer are the FOLD
  file's edges of that kind, scaled to mm (to 1e-9 relative).
- SVG: every crease is its dashes: collinear with it, inside the crease less the vertex gap at
  each end, not overlapping, the dashes' total length the formula's (to 1e-9) and covering the
  stretch as dash / (dash + gap) does (within one period).
Exit 77 (skip) when gdspy or ezdxf is not installed.
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import warnings
import xml.etree.ElementTree as ET

try:
    import ezdxf
    import gdspy
except ImportError as exc:  # pragma: no cover - the install script provides them
    print(f"SKIP: {exc.name} is not installed (scripts/install-deps.sh installs python3-gdspy and python3-ezdxf)")
    sys.exit(77)

ORIKIN, SRC = sys.argv[1], sys.argv[2]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(*args):
    r = subprocess.run([ORIKIN, *args], capture_output=True, text=True, cwd=SRC)
    if r.returncode != 0:
        sys.exit(f"orikin {' '.join(args)}: exit {r.returncode}: {r.stderr}")
    return r.stdout


def load_fold(path):
    with open(path) as f:
        return json.load(f)


def gds_case(fold_path, out_dir, extra):
    out = os.path.join(out_dir, os.path.basename(fold_path).replace(".fold", ".gds"))
    report = json.loads(run("fab", fold_path, "-o", out, "--json", *extra))
    check(os.path.exists(report["layer_map"]), f"{fold_path}: the layer map {report['layer_map']} is written")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lib = gdspy.GdsLibrary(infile=out, units="import")
    check(math.isclose(lib.precision, report["database_unit"], rel_tol=1e-12), f"{fold_path}: database unit {lib.precision} (gdspy decodes the real with rounding)")
    scale = lib.unit / lib.precision  # file user units → database units (1000)
    cell = lib.cell_dict["DEVICE"]

    def q(p):
        return (int(round(p[0] * scale)), int(round(p[1] * scale)))

    want_poly, want_path, want_text = {}, {}, []
    for s in report["shapes"]:
        pts = tuple(tuple(p) for p in s["points"])
        if s["kind"] == "polygon":
            want_poly.setdefault(s["layer"], []).append(pts)
        elif s["kind"] == "path":
            want_path.setdefault(s["layer"], []).append((pts, s["width"]))
        else:
            want_text.append((s["layer"], s["text"], pts[0]))
    got_poly, got_path = {}, {}
    for ps in cell.polygons:
        for poly, layer in zip(ps.polygons, ps.layers):
            got_poly.setdefault(layer, []).append(tuple(q(p) for p in poly))
    for fp in cell.paths:
        got_path.setdefault(fp.layers[0], []).append((tuple(q(p) for p in fp.points), int(round(fp.widths[0][0] * scale))))
    got_text = [(lb.layer, lb.text, q(lb.position)) for lb in cell.labels]
    diffs = 0
    for layer in sorted(set(want_poly) | set(got_poly)):
        w, g = sorted(want_poly.get(layer, [])), sorted(got_poly.get(layer, []))
        diffs += sum(a != b for a, b in zip(w, g)) + abs(len(w) - len(g))
        check(w == g, f"{fold_path}: layer {layer}: {len(g)} polygons read, {len(w)} written, identical")
    for layer in sorted(set(want_path) | set(got_path)):
        w, g = sorted(want_path.get(layer, [])), sorted(got_path.get(layer, []))
        diffs += sum(a != b for a, b in zip(w, g)) + abs(len(w) - len(g))
        check(w == g, f"{fold_path}: layer {layer}: paths identical")
    check(sorted(want_text) == sorted(got_text), f"{fold_path}: text {got_text} == {want_text}")
    check(diffs == 0, f"{fold_path}: {diffs} differences at the database unit")
    # Independent of the CLI's report: one panel per face of the FOLD file, inside its face.
    fold = load_fold(os.path.join(SRC, fold_path))
    faces = fold["faces_vertices"]
    coords = fold["vertices_coords"]
    panels = got_poly.get(1, [])
    check(len(panels) == len(faces), f"{fold_path}: {len(panels)} panels for {len(faces)} faces")
    dbu_per_unit = report["meters_per_unit"] / report["database_unit"]
    for panel in panels:
        cx = sum(p[0] for p in panel) / len(panel) / dbu_per_unit
        cy = sum(p[1] for p in panel) / len(panel) / dbu_per_unit
        inside = 0
        for f in faces:
            poly = [coords[v] for v in f]
            if point_in_polygon(cx, cy, poly):
                inside += 1
                area_face = abs(shoelace(poly))
                area_panel = abs(shoelace(panel)) / dbu_per_unit ** 2
                check(0 < area_panel < area_face, f"{fold_path}: a panel ({area_panel:g}) is smaller than its face ({area_face:g})")
        check(inside == 1, f"{fold_path}: a panel's centroid lies in exactly one face")
    print(f"gds {fold_path}: {sum(len(v) for v in got_poly.values())} polygons, "
          f"{sum(len(v) for v in got_path.values())} paths, {len(got_text)} texts read back by gdspy {gdspy.__version__}: "
          f"{diffs} differences")


def shoelace(poly):
    return 0.5 * sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
                     for i in range(len(poly)))


def point_in_polygon(x, y, poly):
    inside = False
    for i in range(len(poly)):
        (x0, y0), (x1, y1) = poly[i][:2], poly[(i + 1) % len(poly)][:2]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            inside = not inside
    return inside


KIND = {"B": "CUT", "C": "CUT", "M": "MOUNTAIN", "V": "VALLEY", "U": "UNASSIGNED"}


def dxf_case(fold_path, out_dir, mm_per_unit):
    out = os.path.join(out_dir, os.path.basename(fold_path).replace(".fold", ".dxf"))
    run("fab", fold_path, "-o", out, "--scale", repr(mm_per_unit))
    doc = ezdxf.readfile(out)
    auditor = doc.audit()
    check(len(auditor.errors) == 0, f"{fold_path}: ezdxf audit: {len(auditor.errors)} errors {[e.message for e in auditor.errors]}")
    fold = load_fold(os.path.join(SRC, fold_path))
    c = fold["vertices_coords"]
    want = {}
    for (a, b), asg in zip(fold["edges_vertices"], fold["edges_assignment"]):
        if asg in KIND:
            seg = tuple(sorted([(c[a][0] * mm_per_unit, c[a][1] * mm_per_unit), (c[b][0] * mm_per_unit, c[b][1] * mm_per_unit)]))
            want.setdefault(KIND[asg], []).append(seg)
    got = {}
    for e in doc.modelspace().query("LINE"):
        s, t = e.dxf.start, e.dxf.end
        got.setdefault(e.dxf.layer, []).append(tuple(sorted([(s.x, s.y), (t.x, t.y)])))
    size = max(max(abs(x) for x, _ in c), max(abs(y) for _, y in c)) * mm_per_unit
    for layer in sorted(set(want) | set(got)):
        w, g = sorted(want.get(layer, [])), sorted(got.get(layer, []))
        same = len(w) == len(g) and all(math.dist(p, r) <= 1e-9 * size for a, b in zip(w, g) for p, r in zip(a, b))
        check(same, f"{fold_path}: DXF layer {layer}: {len(g)} segments read, {len(w)} in the FOLD file, the same")
    check(set(doc.layers.get(n).dxf.name for n in ("CUT", "MOUNTAIN", "VALLEY")) == {"CUT", "MOUNTAIN", "VALLEY"},
          f"{fold_path}: the layer table has CUT, MOUNTAIN, VALLEY")
    print(f"dxf {fold_path}: {sum(len(v) for v in got.values())} lines, ezdxf {ezdxf.__version__} audit: "
          f"{len(auditor.errors)} errors")


def svg_case(fold_path, out_dir, mm_per_unit, dash, gap, vgap, perforate=False):
    out = os.path.join(out_dir, os.path.basename(fold_path).replace(".fold", "-perf.svg" if perforate else ".svg"))
    args = ["fab", fold_path, "-o", out, "--scale", repr(mm_per_unit), "--vertex-gap", repr(vgap)]
    if perforate:
        args += ["--perforate", "--slit", repr(dash), "--pitch", repr(dash + gap)]
    else:
        args += ["--dash", repr(dash), "--dash-gap", repr(gap)]
    run(*args)
    ns = {"s": "http://www.w3.org/2000/svg"}
    root = ET.parse(out).getroot()
    check(root.get("width").endswith("mm"), f"{out}: width in mm")
    fold = load_fold(os.path.join(SRC, fold_path))
    c = fold["vertices_coords"]
    xs, ys = [p[0] for p in c], [p[1] for p in c]
    margin = 0.2  # two stroke widths (0.1 mm)

    def page(p):
        return ((p[0] - min(xs)) * mm_per_unit + margin, (max(ys) - p[1]) * mm_per_unit + margin)

    groups = {g.get("id"): g for g in root.findall("s:g", ns)}
    check(groups["mountain"].get("stroke") != groups["valley"].get("stroke"), "mountain and valley in different colours")
    creases = 0
    for e, ((a, b), asg) in enumerate(zip(fold["edges_vertices"], fold["edges_assignment"])):
        if asg not in ("M", "V"):
            continue
        creases += 1
        g = groups["mountain" if asg == "M" else "valley"].find(f"s:g[@id='e{e}']", ns)
        check(g is not None, f"crease {e} has its group")
        pa, pb = page(c[a]), page(c[b])
        length = math.dist(pa, pb)
        ux, uy = (pb[0] - pa[0]) / length, (pb[1] - pa[1]) / length
        spans = []
        for ln in g.findall("s:line", ns):
            p = (float(ln.get("x1")), float(ln.get("y1")))
            r = (float(ln.get("x2")), float(ln.get("y2")))
            for pt in (p, r):  # on the crease
                off = abs((pt[0] - pa[0]) * uy - (pt[1] - pa[1]) * ux)
                check(off <= 1e-9 * length, f"crease {e}: a dash off its line by {off}")
            s = (p[0] - pa[0]) * ux + (p[1] - pa[1]) * uy
            t = (r[0] - pa[0]) * ux + (r[1] - pa[1]) * uy
            spans.append((min(s, t), max(s, t)))
        spans.sort()
        stretch = length - 2 * vgap
        n = 0 if stretch <= 0 else 1 if stretch <= dash else math.floor((stretch + gap) / (dash + gap))
        total = sum(t - s for s, t in spans)
        want_total = 0 if stretch <= 0 else stretch if stretch <= dash else n * dash
        check(len(spans) == n, f"crease {e}: {len(spans)} dashes, want {n}")
        check(abs(total - want_total) <= 1e-9 * length, f"crease {e}: dashes cover {total} mm, want {want_total}")
        if stretch > dash + gap:
            check(abs(total / stretch - dash / (dash + gap)) <= (dash + gap) / stretch,
                  f"crease {e}: coverage {total / stretch:.4f} vs dash/(dash+gap) {dash / (dash + gap):.4f}")
        if spans:
            check(spans[0][0] >= vgap - 1e-9 and spans[-1][1] <= length - vgap + 1e-9,
                  f"crease {e}: the dashes skip {vgap} mm at each vertex")
            check(all(spans[i][1] < spans[i + 1][0] for i in range(len(spans) - 1)), f"crease {e}: dashes do not overlap")
    cuts = len(groups["cut"].findall("s:line", ns))
    check(cuts == sum(a in ("B", "C") for a in fold["edges_assignment"]), f"{out}: one solid line per cut edge")
    print(f"svg {fold_path}{' perforated' if perforate else ''}: {creases} creases, dashes checked")


with tempfile.TemporaryDirectory() as tmp:
    gds_case("examples/patterns/open-corner-gold.fold", tmp, ["--fix", "4"])
    gds_case("examples/patterns/thesis-flap.fold", tmp, [])
    # a bigger pattern: a generated Miura-ori, unitless, read as millimetres
    miura = os.path.join(tmp, "miura.fold")
    run("generate", "miura", "--rows", "6", "--cols", "8", "--angle", "70", "-o", miura)
    gds_case(miura, tmp, ["--unit", "mm", "--gap", "0.02"])
    dxf_case("examples/patterns/open-corner.fold", tmp, 50.0)
    dxf_case(miura, tmp, 20.0)
    svg_case("examples/patterns/open-corner.fold", tmp, 50.0, 3.0, 1.5, 1.0)
    svg_case(miura, tmp, 20.0, 2.0, 1.0, 0.8)
    svg_case(miura, tmp, 20.0, 0.5, 1.0, 0.8, perforate=True)

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("all fabrication files read back")
