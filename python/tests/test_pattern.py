"""Patterns in and out: files, FOLD dicts, arrays, sheets, generators, authoring edits."""

import json
import math

import numpy as np
import pytest

import orikin
from conftest import cli, open_corner, repo, shared


def test_load_reads_what_the_cli_reads():
    p = open_corner()
    info = json.loads(cli("info examples/patterns/open-corner.fold --json").stdout)
    assert (p.vertex_count, p.edge_count, p.face_count) == (info["vertices"], info["edges"], info["faces"])
    assert p.assignment == "BBBBBBMBVVBVV" and p.interior_vertex_count == 1
    assert p.face_names[4] == "Obj1212" and p.frame_count == 1 and not p.is_folded_form
    assert p.vertices.shape == (9, 3) and p.edges.shape == (13, 2) and p.diagonal == pytest.approx(2 * math.sqrt(2))
    assert sorted(len(f) for f in p.faces) == [3, 3, 4, 4, 4]


def test_fold_dicts_round_trip_with_unknown_fields_kept():
    p = open_corner()
    d = p.to_fold()
    d["custom:note"] = {"kept": [1, 2, 3]}
    q = orikin.Pattern.from_fold(d)
    assert q.to_fold()["custom:note"] == {"kept": [1, 2, 3]}
    assert np.array_equal(q.vertices, p.vertices) and np.array_equal(q.edges, p.edges)
    assert q.assignment == p.assignment and q.faces == p.faces and q.face_names == p.face_names
    assert orikin.Pattern.from_fold(json.dumps(d)).to_fold() == q.to_fold()


def test_arrays_make_the_same_pattern_as_the_file():
    p = open_corner()
    q = orikin.Pattern.from_arrays(p.vertices[:, :2], p.edges, p.assignment, p.faces)
    assert np.array_equal(q.vertices, p.vertices) and q.faces == p.faces
    # Folding it gives the thesis' values too (names are not part of the arrays).
    m = q.fold(fix=4, drive=12, lock=[11], to=90)
    assert m.angles[-1, 9] == pytest.approx(math.pi / 3, abs=1e-12)
    # Faces traced when not given; fold angles in degrees both ways.
    r = orikin.Pattern.from_arrays(p.vertices, p.edges, list(p.assignment), fold_angles=np.full(13, 45.0))
    assert r.face_count == 5 and r.has_fold_angles and r.fold_angles == pytest.approx(np.full(13, 45.0))
    assert r.to_fold()["edges_foldAngle"] == pytest.approx([45.0] * 13)


def test_a_sheet_creased_by_the_collection_is_the_open_corner():
    # The thesis' construction (SPEC item 14): MiddleH, MiddleV on both halves, DiagonalL.
    s = orikin.Pattern.sheet([(0, 0), (2, 0), (2, 2), (0, 2)])
    assert s.face_count == 1 and s.face_names == ["Obj1"]
    s = s.apply("middle-h", face="Obj1")
    s = s.apply("middle-v", face="Obj11").apply("middle-v", face="Obj12")
    assert sorted(n for n in s.face_names) == ["Obj111", "Obj112", "Obj121", "Obj122"]
    lower_left = s.face((0.5, 0.5))
    s = s.apply("diagonal-left", face=lower_left)
    assert s.face_count == 5 and s.interior_vertex_count == 1
    v = s.vertices
    centre = int(np.argmin(np.hypot(v[:, 0] - 1, v[:, 1] - 1)))
    degree = sum(centre in e for e in s.edges.tolist())
    assert degree == 5


def test_crease_edits_return_new_patterns():
    sq = orikin.Pattern.square(2)
    c = sq.crease((0, 0), (2, 2), assignment="M")
    assert sq.edge_count == 4 and c.edge_count == 5 and c.assignment.count("M") == 1
    e = c.edge((1.0, 1.0))
    assert c.flip(e).assignment[e] == "V" and c.assign(e, "U").assignment[e] == "U"
    assert c.remove(e).edge_count == 4 and c.remove(e).face_count == 1
    mv = c.move(e, (0, 2), (2, 0))
    assert mv.edge((0.5, 1.5)) is not None and mv.assignment.count("M") == 1
    # A line from an axiom: fold (0, 0) onto (2, 2), the other diagonal.
    (line,) = orikin.axiom(2, p1=(0, 0), p2=(2, 2))
    d = sq.crease(line=line, assignment="V")
    assert d.edge((0.5, 1.5)) >= 0 and d.face_count == 2
    # A segment only between its points: a slit from the boundary.
    s = sq.crease((0, 1), (1, 1), segment=True, assignment="V")
    assert s.edge_count == 6 and s.face_count == 1  # the boundary edge split where the slit starts
    with pytest.raises(orikin.InputError):
        sq.crease((5, 0), (5, 1))  # the line x = 5 misses the sheet


def test_axioms_give_every_solution():
    assert orikin.axiom(1, p1=(0, 0), p2=(1, 0)) == [((0.0, 0.0), (1.0, 0.0))]
    assert len(orikin.axiom(3, l1=((0, 0), (1, 0)), l2=((0, 0), (0, 1)))) == 2
    sols = orikin.axiom(6, p1=(0, 1), l1=((0, -1), (1, 0)), p2=(2, 0), l2=((-1, 0), (0, 1)))
    assert 0 <= len(sols) <= 3
    with pytest.raises(TypeError, match="needs p2"):
        orikin.axiom(2, p1=(0, 0))
    with pytest.raises(ValueError):
        orikin.axiom(8, p1=(0, 0))


def test_generated_patterns_are_the_clis(tmp_path):
    out = tmp_path / "m.fold"
    assert cli(f"generate miura --rows 3 --cols 4 -o {out}").returncode == 0
    want = orikin.Pattern.load(out)
    got = orikin.generate("miura", rows=3, cols=4)
    assert np.array_equal(got.vertices, want.vertices) and got.assignment == want.assignment
    assert got.to_fold()["orikin:edges_class"] == want.to_fold()["orikin:edges_class"]
    k = orikin.generate("kresling")
    assert k.face_count > 0
    with pytest.raises(ValueError, match="unknown tessellation"):
        orikin.generate("hexagon")
    with pytest.raises(orikin.InputError):
        orikin.generate("miura", rows=0)


def test_drawings_load_and_save(tmp_path):
    p = open_corner()
    for ext in ("svg", "cp", "opx"):
        path = tmp_path / f"oc.{ext}"
        p.save(path)
        q = orikin.Pattern.load(path)
        assert q.edge_count == p.edge_count and sorted(q.assignment) == sorted(p.assignment)
    p.save(tmp_path / "oc.fold")
    assert orikin.Pattern.load(tmp_path / "oc.fold").to_fold() == p.to_fold()


def test_a_shared_drawing_folds_from_its_svg():
    path = shared("origamisimulator")
    import glob
    svgs = sorted(glob.glob(path + "/*.svg"))
    if not svgs:
        pytest.skip("no Origami Simulator SVG")
    p = orikin.Pattern.load(svgs[0])
    assert p.edge_count > 0 and p.face_count > 0


def test_a_crease_without_an_assignment_is_unassigned_as_the_cli_makes_it():
    # fuzz_python's first find (fuzz/seeds/python/crease-no-assignment): the extension read the
    # optional assignment it had not initialised, a NULL dereference when it was omitted.
    p = orikin.Pattern.load(repo("examples/patterns/open-corner.fold"))._p
    q, what = p.crease((0.5, 0.0), (0.5, 2.0))
    # x = 0.5 crosses faces 1, 3 and 4: three new crease segments, the last edges added
    assert what["faces_split"] == 3 and q.assignment()[-3:] == "UUU"
    q, what = p.crease((0.5, 0.0), (0.5, 2.0), assignment="M")
    assert what["faces_split"] == 3 and q.assignment()[-3:] == "MMM"
    with pytest.raises(ValueError, match="assignment must be one FOLD letter"):
        p.crease((0.5, 0.0), (0.5, 2.0), assignment=None)


def test_pose_refuses_angles_none():
    # fuzz_python's second find (fuzz/seeds/python/pose-angles-none): None passed the optional
    # start's check and reached ori_mechanism_pose_state's assertion (a NULL state: abort).
    p = orikin.Pattern.load(repo("examples/patterns/open-corner.fold"))._p
    with pytest.raises(ValueError, match="angles must be a 1-D array of numbers"):
        p.pose(None, 4)
    angles, positions = p.pose(np.zeros(p.edge_count), 4)
    assert angles.shape == (13,) and positions.shape == (9, 3)
    assert np.max(np.abs(angles)) == 0.0 and np.max(np.abs(positions[:, 2])) == 0.0  # the flat state stays flat
