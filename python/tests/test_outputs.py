"""Pictures, meshes, animations, self-collision, unfolding."""

import json
import math
import struct

import numpy as np
import pytest

import orikin
from conftest import cli, open_corner, repo


def corner_cube():
    return open_corner().fold(fix=4, drive=12, lock=[11], to=180)


def test_render_draws_the_crease_pattern_and_the_folded_sheet(tmp_path):
    p = open_corner()
    png = p.render(size=(320, 240))
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    w, h = struct.unpack(">II", png[16:24])
    assert (w, h) == (320, 240)
    svg = corner_cube().render(format="svg", camera="top", yaw=30)
    assert svg.lstrip().startswith(b"<?xml") and b"<svg" in svg
    pdf = corner_cube().render(format="pdf")
    assert pdf[:5] == b"%PDF-"
    out = tmp_path / "cube.png"
    assert corner_cube().render(out, front="red", back="#00f", grid=True, perspective=True) is None
    assert out.read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(ValueError, match="camera"):
        p.render(camera="sideways")
    with pytest.raises(ValueError, match="colour"):
        p.render(front="not-a-colour")


def test_export_writes_every_mesh_format(tmp_path):
    m = corner_cube()
    obj = m.export(format="obj").decode()
    vs = [line for line in obj.splitlines() if line.startswith("v ")]
    assert len(vs) == 9  # OBJ vertex i = FOLD vertex i-1
    x, y, z = map(float, vs[0].split()[1:])
    assert (x, y, z) == pytest.approx(tuple(m.vertices[-1][0]), abs=1e-12)
    glb = m.export()
    assert glb[:4] == b"glTF" and struct.unpack("<I", glb[4:8])[0] == 2
    stl = m.export(format="stl", thickness=0.05)
    assert stl.startswith(b"solid")
    anim = json.loads(m.export(format="gltf", animate=True))
    assert anim["animations"] and len(anim["nodes"]) >= m.pattern.face_count
    m.export(tmp_path / "c.ply")
    assert (tmp_path / "c.ply").read_bytes().startswith(b"ply")


def test_animate_writes_a_gif_of_every_frame(tmp_path):
    m = corner_cube()
    gif = m.animate(size=(160, 120), fps=10)
    assert gif[:6] == b"GIF89a"
    assert struct.unpack("<HH", gif[6:10]) == (160, 120)
    assert gif.count(b"\x21\xf9\x04") == m.frame_count  # one graphic control block per frame
    seen = []
    m.animate(tmp_path / "a.gif", size=(80, 60), progress=seen.append)
    assert (tmp_path / "a.gif").stat().st_size > 0 and seen[-1] == pytest.approx(1.0)


def test_collide_finds_the_crossing_flaps_as_the_cli_does():
    p = orikin.Pattern.load(repo("tests/data/collide-flaps-crossing.fold"))
    c = p.collide()
    j = json.loads(cli("collide tests/data/collide-flaps-crossing.fold --json").stdout)
    assert c.collides and c.penetrating == 1 and [list(k.faces) for k in c.contacts] == j["pairs"]
    assert c.contacts[0].kind == "penetrating" and c.witness == pytest.approx(tuple(j["witness"]), abs=1e-12)
    # A clean state: the flat sheet; the corner cube touches nowhere it should not.
    assert not open_corner().collide().collides
    assert not corner_cube().frame(-1).collide().collides


def test_unfold_a_cube_into_all_eleven_nets():
    net = orikin.unfold(repo("tests/data/unfold/cube.obj"), all=True)
    assert net.pieces == 1 and net.overlaps == 0 and net.distinct_nets == 11 and net.spanning_trees == 384
    assert net.refolded and net.max_refold_error <= 1e-12 and net.cuts == 7
    assert net.pattern.face_count == 6 and net.vertex_position.shape == (net.pattern.vertex_count, 3)


def test_unfold_from_arrays_and_a_hull():
    v = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], float)
    faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]
    net = orikin.unfold(vertices=v, faces=faces)
    assert net.pieces == 1 and net.pattern.face_count == 4
    hull = orikin.unfold(vertices=np.vstack([v, [(0.1, 0.1, 0.1)]]), hull=True)
    assert hull.pattern.face_count == 4
    with pytest.raises(ValueError, match="vertex 9"):
        orikin.unfold(vertices=v, faces=[[0, 1, 9]])


def test_a_folded_form_develops_into_its_crease_pattern():
    net = orikin.unfold(repo("tests/data/unfold/miura-folded.obj"), develop=True)
    assert net.developed and net.cuts == 0 and net.fold_residual <= 1e-9
    assert "M" in net.pattern.assignment and "V" in net.pattern.assignment


def test_a_linkage_straightens_without_shortening_a_bar():
    coords = [(0, 0), (1, 0), (1, 1), (0, 1), (0.2, 0.5)]
    lk = orikin.unfold_linkage(coords, [(0, 1), (1, 2), (2, 3), (3, 4)])
    assert lk.kind == "chain" and lk.final_ok and lk.max_length_error <= 1e-9 and lk.min_distance_change >= -1e-9
    last = lk.frames[-1]
    d = np.diff(last, axis=0)
    turn = np.cross(d[:-1], d[1:])
    assert np.abs(turn).max() <= 1e-6  # straight
