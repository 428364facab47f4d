#!/usr/bin/env python3
"""Every writer of orikin read back by a reader that is not orikin's (issue 27, docs/fuzzing.md).

usage: writers_readback.py ORIKIN SOURCE_DIR [RANDOM_PATTERNS]

On the example patterns and on RANDOM_PATTERNS (default 12) generated tessellations of random
kind, size and angle (seeded, so a failure repeats), each writer's output is read by an
independent reader and its values compared with what orikin reports (--json):

- FOLD (convert, fold -o): Python's json module; vertex, edge and face counts equal to
  `convert --json`; the fold's frames' edges_foldAngle equal to `fold --json`'s angles to 1e-12.
- SVG, OPX (convert, render): xmllint --noout (well-formed XML); a render's width and height
  equal to --size.
- CP (convert): every line a type and 4 numbers, at least one per crease.
- PNG (render) and GIF (animate): Pillow; image size equal to --size, the GIF's frame count
  equal to `animate --json`'s frames.
- PDF (render): pdfinfo; one page, its size equal to --size in points.
- OBJ, STL, PLY (export): parsed here from the format's own definition; triangle counts equal to
  both sides of `export --json`'s triangles (a thick export's panel solids: at least that).
- glTF, GLB (export): Python's json (the GLB's JSON chunk) for the accessor counts, and the Khronos
  gltf-validator (node_modules) with no errors.

A reader that is missing (xmllint, pdfinfo, Pillow, node/gltf-validator) skips its checks and says
so; exit 77 (skip) only when none is present.
"""
import json
import os
import random
import shutil
import struct
import subprocess
import sys
import tempfile

ORIKIN, SRC = sys.argv[1], sys.argv[2]
NRANDOM = int(sys.argv[3]) if len(sys.argv) > 3 else 12
os.chdir(SRC)
failures = []
checks = 0

try:
    from PIL import Image
except ImportError:
    Image = None
HAVE_XMLLINT = shutil.which("xmllint") is not None
HAVE_PDFINFO = shutil.which("pdfinfo") is not None
HAVE_VALIDATOR = shutil.which("node") is not None and os.path.exists("node_modules/gltf-validator/package.json")
if not (Image or HAVE_XMLLINT or HAVE_PDFINFO or HAVE_VALIDATOR):
    print("SKIP: none of the readers (Pillow, xmllint, pdfinfo, gltf-validator) is installed")
    sys.exit(77)
for have, what in ((Image, "Pillow (python3-pil)"), (HAVE_XMLLINT, "xmllint"), (HAVE_PDFINFO, "pdfinfo"),
                   (HAVE_VALIDATOR, "node_modules/gltf-validator")):
    if not have:
        print(f"note: {what} is missing: its checks are skipped")


def check(cond, what):
    global checks
    checks += 1
    if not cond:
        failures.append(what)
        print("FAIL:", what)
    return cond


def run(*args, refusable=False):
    r = subprocess.run([ORIKIN, *args], capture_output=True, text=True)
    if r.returncode == 3 and refusable and "not a folded state" in r.stderr:
        print(f"note: orikin {' '.join(args)}: refused as input ({r.stderr.strip()[:120]})")
        return None
    if r.returncode != 0:
        failures.append(f"orikin {' '.join(args)}: exit {r.returncode}")
        print(f"FAIL: orikin {' '.join(args)}: exit {r.returncode}: {r.stderr.strip()[:300]}")
        return None
    return r.stdout


def run_json(*args, refusable=False):
    out = run(*args, "--json", refusable=refusable)
    return json.loads(out) if out is not None else None


def xml_ok(path):
    if not HAVE_XMLLINT:
        return
    r = subprocess.run(["xmllint", "--noout", "--nonet", path], capture_output=True, text=True)
    check(r.returncode == 0, f"{path}: xmllint: {r.stderr.strip()[:200]}")


def fold_counts(doc):
    nv = len(doc.get("vertices_coords", []))
    ne = len(doc.get("edges_vertices", []))
    nf = len(doc.get("faces_vertices", []))
    return nv, ne, nf


def convert_case(name, src, tmp):
    """FOLD, SVG, OPX, CP written by convert, read back independently."""
    for ext in ("fold", "svg", "opx", "cp"):
        out = os.path.join(tmp, f"{name}.{ext}")
        rep = run_json("convert", src, "-o", out)
        if rep is None:
            continue
        if ext == "fold":
            with open(out) as f:
                doc = json.load(f)
            check(fold_counts(doc) == (rep["vertices"], rep["edges"], rep["faces"]),
                  f"{out}: counts {fold_counts(doc)} against convert --json {rep['vertices'], rep['edges'], rep['faces']}")
            check(all(len(c) in (2, 3) and all(isinstance(x, (int, float)) for x in c) for c in doc["vertices_coords"]),
                  f"{out}: vertices_coords are 2 or 3 numbers")
            check(all(0 <= v < rep["vertices"] for e in doc["edges_vertices"] for v in e), f"{out}: edge indices in range")
            check(len(doc.get("edges_assignment", [])) == rep["edges"], f"{out}: one assignment per edge")
        elif ext in ("svg", "opx"):
            xml_ok(out)
        else:
            with open(out) as f:
                rows = [ln.split() for ln in f if ln.strip()]
            check(all(len(r) == 5 and r[0] in "1234" for r in rows), f"{out}: every CP line is a type and 4 numbers")
            for r in rows:
                [float(x) for x in r[1:]]
            creases = sum(n for k, n in rep["edges_by_assignment"].items() if k != "B")
            check(len(rows) >= creases, f"{out}: {len(rows)} CP lines for {creases} creases")


def fold_case(name, src, args, tmp):
    """A fold's FOLD frames against its --json, to 1e-12 (degrees through the JSON)."""
    out = os.path.join(tmp, f"{name}-fold.fold")
    rep = run_json("fold", src, *args, "-o", out)
    if rep is None:
        return
    with open(out) as f:
        doc = json.load(f)
    frames = doc.get("file_frames", [])
    want = [fr["fold_angles_deg"] for fr in rep["frames"]]
    # frame 0 of the file is the first state; the others are in file_frames
    got = [doc.get("edges_foldAngle")] + [fr.get("edges_foldAngle") for fr in frames]
    got = [g for g in got if g is not None]
    if not check(len(got) >= len(want), f"{out}: {len(got)} frames with edges_foldAngle for {len(want)} states"):
        return
    got = got[-len(want):]
    worst = max(abs(a - b) for g, w in zip(got, want) for a, b in zip(g, w))
    check(worst <= 1e-12, f"{out}: fold angles differ from fold --json by {worst:g} deg")


def render_case(name, src, state, tmp, w, h):
    for ext in ("svg", "pdf", "png"):
        out = os.path.join(tmp, f"{name}-render.{ext}")
        if run("render", src, *state, "--size", f"{w}x{h}", "-o", out) is None:
            continue
        if ext == "svg":
            xml_ok(out)
            import xml.etree.ElementTree as ET
            root = ET.parse(out).getroot()
            ww = float(root.get("width").rstrip("ptx"))
            hh = float(root.get("height").rstrip("ptx"))
            check((ww, hh) == (w, h), f"{out}: SVG size {ww}x{hh}, asked {w}x{h}")
        elif ext == "pdf" and HAVE_PDFINFO:
            r = subprocess.run(["pdfinfo", out], capture_output=True, text=True)
            if check(r.returncode == 0, f"{out}: pdfinfo: {r.stderr.strip()[:200]}"):
                info = dict(ln.split(":", 1) for ln in r.stdout.splitlines() if ":" in ln)
                check(info["Pages"].strip() == "1", f"{out}: {info['Pages'].strip()} pages")
                size = info["Page size"].split()
                check((float(size[0]), float(size[2])) == (w, h), f"{out}: page size {info['Page size'].strip()}, asked {w}x{h}")
        elif ext == "png" and Image:
            with Image.open(out) as im:
                im.load()
                check(im.format == "PNG" and im.size == (w, h), f"{out}: {im.format} {im.size}, asked {(w, h)}")


def animate_case(name, src, state, tmp):
    if not Image:
        return
    out = os.path.join(tmp, f"{name}.gif")
    rep = run_json("animate", src, *state, "--size", "96x64", "--fps", "5", "--duration", "1", "-o", out)
    if rep is None:
        return
    with Image.open(out) as im:
        n = 0
        try:
            while True:
                im.seek(n)
                im.load()
                check(im.size == (96, 64), f"{out}: frame {n} is {im.size}")
                n += 1
        except EOFError:
            pass
    check(im.format == "GIF" and n == rep["frames"], f"{out}: {n} GIF frames, animate --json says {rep['frames']}")


def obj_counts(path):
    nv = nf = 0
    with open(path) as f:
        for ln in f:
            t = ln.split()
            if not t:
                continue
            if t[0] == "v":
                check(len(t) == 4, f"{path}: a vertex of 3 coordinates")
                [float(x) for x in t[1:]]
                nv += 1
            elif t[0] == "f":
                idx = [int(x.split("/")[0]) for x in t[1:]]
                check(len(idx) == 3 and all(1 <= i for i in idx), f"{path}: a triangle of 1-based indices")
                nf += 1
    return nv, nf


def stl_triangles(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:5] == b"solid" and b"facet" in data[:1000]:
        return data.count(b"endfacet")
    n = struct.unpack_from("<I", data, 80)[0]
    check(len(data) == 84 + 50 * n, f"{path}: binary STL of {n} triangles is {84 + 50 * n} bytes, not {len(data)}")
    return n


def ply_counts(path):
    with open(path, "rb") as f:
        data = f.read()
    head = data[:data.index(b"end_header")].decode("ascii").splitlines()
    check(head[0] == "ply", f"{path}: starts with ply")
    el = {ln.split()[1]: int(ln.split()[2]) for ln in head if ln.startswith("element")}
    return el.get("vertex", 0), el.get("face", 0)


def gltf_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if path.endswith(".glb"):
        magic, version, length = struct.unpack_from("<4sII", data, 0)
        check(magic == b"glTF" and version == 2 and length == len(data), f"{path}: GLB header")
        clen, ctype = struct.unpack_from("<I4s", data, 12)
        check(ctype == b"JSON", f"{path}: first chunk JSON")
        return json.loads(data[20:20 + clen])
    return json.loads(data)


def export_case(name, src, state, tmp, gltfs, refusable=False):
    """Meshes: a sheet is both sides of every triangle (2 x triangles); a thick one closed panel
    solids (more)."""
    for ext in ("obj", "stl", "ply", "gltf", "glb"):
        out = os.path.join(tmp, f"{name}.{ext}")
        rep = run_json("export", src, *state, "-o", out, refusable=refusable)
        if rep is None:
            continue
        thick = rep.get("thickness", 0) not in (0, None)
        tri = rep["triangles"] if thick else 2 * rep["triangles"]
        if thick:  # the solids: at least the sheet's two sides; compared as a lower bound
            tri_check = lambda n: n >= 2 * rep["triangles"]  # noqa: E731
        else:
            tri_check = lambda n: n == tri  # noqa: E731
        if ext == "obj":
            nv, nf = obj_counts(out)
            check(tri_check(nf), f"{out}: {nf} faces, export --json says {tri} triangles")
            check(nv >= rep["vertices"], f"{out}: {nv} vertices for {rep['vertices']}")
            check(os.path.exists(out[:-4] + ".mtl") or os.path.exists(out + ".mtl"), f"{out}: its .mtl")
        elif ext == "stl":
            n = stl_triangles(out)
            check(tri_check(n), f"{out}: {n} STL triangles, export --json says {tri}")
        elif ext == "ply":
            nv, nf = ply_counts(out)
            check(tri_check(nf), f"{out}: {nf} PLY faces, export --json says {tri}")
            check(nv >= rep["vertices"], f"{out}: {nv} PLY vertices for {rep['vertices']}")
        else:
            g = gltf_json(out)
            idx = sum(g["accessors"][p["indices"]]["count"] for m in g["meshes"] for p in m["primitives"] if "indices" in p)
            check(idx % 3 == 0 and tri_check(idx // 3), f"{out}: {idx} indices for {tri} triangles")
            gltfs.append(out)


def patterns():
    """(name, file, fold arguments or None) for the examples and random tessellations."""
    out = []
    for f in sorted(os.listdir("examples/patterns")):
        if f.endswith(".fold"):
            out.append((f[:-5], os.path.join("examples/patterns", f), None))
    return out


def main():
    rng = random.Random(27)
    tmp = tempfile.mkdtemp(prefix="orikin-readback-")
    gltfs = []
    try:
        cases = patterns()
        kinds = ("miura", "yoshimura", "waterbomb", "kresling", "square-twist")
        for i in range(NRANDOM):
            kind = kinds[i % len(kinds)]
            rows, cols = rng.randint(1, 5), rng.randint(1, 5)
            args = ["generate", kind, "--rows", str(rows)]
            args += ["--sides", str(rng.randint(3, 8))] if kind == "kresling" else ["--cols", str(cols)]
            if kind == "yoshimura":
                args += ["--angle", f"{rng.uniform(30, 60):.3f}"]
            elif kind not in ("waterbomb", "square-twist"):
                args += ["--angle", f"{rng.uniform(50, 80):.3f}"]
            path = os.path.join(tmp, f"random-{i}-{kind}.fold")
            if run(*args, "-o", path) is not None:
                cases.append((f"random-{i}-{kind}", path, None))
        for name, src, _ in cases:
            convert_case(name, src, tmp)
            render_case(name, src, ["--view", "cp"], tmp, 160 + len(name), 120)
            export_case(name, src, [], tmp, gltfs, refusable=True)
        # folded states: the thesis' open corner and a sequence
        corner = "examples/patterns/open-corner.fold"
        fold_args = ["--fix", "4", "--drive", "12", "--lock", "11", "--to", "90", "--step", "7"]
        fold_case("open-corner", corner, fold_args, tmp)
        render_case("open-corner-folded", corner, fold_args, tmp, 200, 150)
        export_case("open-corner-folded", corner, fold_args, tmp, gltfs)
        animate_case("open-corner", corner, fold_args, tmp)
        seq = "examples/open-corner.seq.json"
        render_case("open-corner-seq", seq, ["--at", "0.5"], tmp, 240, 180)
        export_case("open-corner-seq", seq, ["--at", "0.5"], tmp, gltfs)
        export_case("open-corner-thick", seq, ["--thickness", "0.05"], tmp, gltfs)
        animate_case("open-corner-seq", seq, [], tmp)
        out = os.path.join(tmp, "open-corner-animated.glb")
        if run("export", seq, "--animate", "-o", out) is not None:
            gltfs.append(out)
        if HAVE_VALIDATOR and gltfs:
            r = subprocess.run(["node", "tests/gltf/validate.js", *gltfs], capture_output=True, text=True)
            check(r.returncode == 0, f"gltf-validator: {r.stdout[-600:]}")
        print(f"{len(cases)} patterns, {checks} checks, {len(failures)} failures"
              f" ({len(gltfs)} glTF/GLB files through gltf-validator)")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failures else 0


sys.exit(main())
