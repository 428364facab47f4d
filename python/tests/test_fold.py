"""Folds: the thesis' open corner, the Miura-ori closed form, the modes for several degrees of
freedom, the state between frames, collisions, progress and cancellation, the GIL."""

import json
import math
import threading
import time

import numpy as np
import pytest

import orikin
from conftest import cli, open_corner as load_open_corner, repo

DIAG, DOWN, RIGHT, UP, LEFT, T2 = 12, 11, 8, 9, 6, 4  # the open corner (docs/kinematics.md §12)


def test_open_corner_indices_are_the_creases_named_by_points():
    open_corner = load_open_corner()
    p = open_corner
    assert p.edge((0.5, 0.5)) == DIAG and p.edge("@1,0.5") == DOWN and p.edge((1.5, 1.0)) == RIGHT
    assert p.edge((1.0, 1.5)) == UP and p.edge((0.5, 1.0)) == LEFT
    assert p.face("Obj1212") == T2 and p.face((0.7, 0.3)) == T2


def test_open_corner_first_fold_gives_the_thesis_values():
    open_corner = load_open_corner()
    m = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=90, step=90)
    assert m.valid and m.verdict == "valid" and m.reason is None
    assert m.frame_count == 2 and m.angles.shape == (2, 13)
    a = m.angles[-1]
    # Θ3 = 60°, Θ4 = asin(1/√3) = 35.26° (the thesis rounds it to 35.5°), exact to the solver.
    assert a[UP] == pytest.approx(math.pi / 3, abs=1e-12)
    assert a[RIGHT] == pytest.approx(math.asin(1 / math.sqrt(3)), abs=1e-12)
    assert a[LEFT] == pytest.approx(-math.asin(1 / math.sqrt(3)), abs=1e-12)
    assert a[DIAG] == pytest.approx(math.pi / 2, abs=1e-15) and a[DOWN] == 0.0
    assert m.residuals.max() <= 1e-10
    # End effector at (0.5, 0.5, 1/√2) in Frame A and (−1.5, −0.5, 1/√2) in Frame B.
    ea, eb = m.end_effector()
    assert ea == pytest.approx((0.5, 0.5, 1 / math.sqrt(2)), abs=1e-12)
    assert eb == pytest.approx((-1.5, -0.5, 1 / math.sqrt(2)), abs=1e-12)
    split = m.split
    assert split["vertex"] == 6 and list(split["frame_a"]) == [DIAG, LEFT]
    assert list(split["frame_b"]) == [RIGHT, UP, LEFT] and list(split["surrounding"]) == [DOWN]
    assert m.solver == "closed-form spherical 4R" and m.kind == "drive" and m.drive == DIAG
    # The mirrored branch (−60°, −35.26°), which the MV assignment rejects, is the other solution.
    other = m.other_branch(-1)
    assert other[UP] == pytest.approx(-math.pi / 3, abs=1e-12)


def test_faces_and_creases_by_name_and_point_fold_the_same():
    open_corner = load_open_corner()
    a = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=90, collisions=False)
    b = open_corner.fold(fix="Obj1212", drive=(0.5, 0.5), lock="@1,0.5", to=90, collisions=False)
    c = open_corner.fold(fix=(0.7, 0.3), drive="@0.5,0.5", lock=[(1.0, 0.5)], to=90, collisions=False)
    assert np.array_equal(a.angles, b.angles) and np.array_equal(a.angles, c.angles)


def test_the_motion_is_the_clis_frame_for_frame():
    open_corner = load_open_corner()
    m = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, step=30)
    r = cli("fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 180 --step 30 --json")
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert j["verdict"] == m.verdict and len(j["frames"]) == m.frame_count
    for k, fr in enumerate(j["frames"]):
        assert np.degrees(m.angles[k]) == pytest.approx(fr["fold_angles_deg"], abs=1e-9)
    assert m.dof == j["dof"] and m.pattern.grubler() == j["grubler"] == -1


def test_no_fix_holds_the_face_at_the_centre_as_the_cli_does():
    open_corner = load_open_corner()
    m = open_corner.fold(drive=DIAG, lock=[DOWN], to=90)
    r = cli("fold examples/patterns/open-corner.fold --drive 12 --lock 11 --to 90 --json")
    assert m.fix_default and m.fixed_face == json.loads(r.stdout)["fixed_face"] == open_corner.center_face()


def test_at_is_the_exact_state_between_frames():
    open_corner = load_open_corner()
    m = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=90, step=30)
    half = m.at(0.5)
    direct = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=45, step=45)
    assert half.drive == pytest.approx(math.pi / 4, abs=1e-15)
    assert half.angles == pytest.approx(direct.angles[-1], abs=1e-12)
    assert half.positions == pytest.approx(direct.vertices[-1], abs=1e-12)
    assert np.array_equal(m.at(0.0).angles, m.angles[0]) and np.array_equal(m.at(1.0).angles, m.angles[-1])
    assert np.array_equal(m.at(1 / 3).angles, m.angles[1])  # on a frame: that frame
    with pytest.raises(ValueError):
        m.at(1.5)


def test_a_second_fold_starts_from_a_frame_or_a_state():
    open_corner = load_open_corner()
    first = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, step=30)
    # As docs/kinematics.md §12: -o first.fold, then fold --frame K --drive 11 --lock 12 --to 90.
    written = orikin.Pattern.from_fold(first.to_fold())
    assert written.frame_count == 1 + first.frame_count
    second = written.fold(frame=written.frame_count - 1, fix=T2, drive=DOWN, lock=[DIAG], to=90)
    assert second.valid, second.reason
    assert np.degrees(second.angles[0, LEFT]) == pytest.approx(-90, abs=1e-9)
    assert np.degrees(second.angles[-1, LEFT]) == pytest.approx(-180, abs=1e-9)
    again = open_corner.fold(start=first.at(1.0), fix=T2, drive=DOWN, lock=[DIAG], to=90)
    assert again.angles == pytest.approx(second.angles, abs=1e-9)
    assert again.vertices == pytest.approx(second.vertices, abs=1e-9)


def test_a_wrong_axis_is_an_invalid_assignment_naming_the_crease():
    p = orikin.Pattern.load(repo("tests/data/kin-open-corner-wrong-axis.fold"))
    r = cli("fold tests/data/kin-open-corner-wrong-axis.fold --fix 4 --drive 12 --lock 11 --to 90 --json")
    m = p.fold(fix=4, drive=12, lock=[11], to=90)
    j = json.loads(r.stdout)
    assert not m.valid and m.verdict == "invalid assignment" == j["verdict"]
    assert m.reason == j["reason"]
    assert [v["edge"] for v in m.violations] == j["offending_edges"]


def test_a_blocked_fold_stops_at_the_crease_limit_and_writes_a_partial_motion():
    p = orikin.Pattern.load(repo("tests/data/kin-issue14-vertex.fold"))
    m = p.fold(fix=3, drive=10, to=-180)
    j = json.loads(cli("fold tests/data/kin-issue14-vertex.fold --fix 3 --drive 10 --to -180 --json").stdout)
    assert m.verdict == "blocked" == j["verdict"] and not m.valid
    assert m.blocked["kind"] == j["blocked"]["kind"]
    assert math.degrees(m.blocked["drive_rad"]) == pytest.approx(j["blocked"]["drive_deg"], abs=1e-9)
    assert m.frame_count == len(j["frames"]) and np.abs(m.angles).max() <= math.pi
    fold = m.to_fold()
    assert fold["orikin:partial"]["verdict"] == "blocked" and fold["orikin:partial"]["frames"] == m.frame_count
    assert len(fold["file_frames"]) == m.frame_count


def test_underdetermined_fold_hints_the_clis_lock_set():
    open_corner = load_open_corner()
    m = open_corner.fold(fix=T2, drive=DIAG, to=90)
    assert m.verdict == "underdetermined" and m.frame_count == 0 and m.angles.shape == (0, 13)
    assert "lock 1 more crease, e.g. lock=[11]" in m.hint
    assert "--lock 11" in cli("fold examples/patterns/open-corner.fold --fix 4 --drive 12 --to 90").stdout


MIURA_A, MIURA_B, MIURA_GAMMA = 1.0, math.hypot(0.4, 0.9), math.atan2(0.9, 0.4)


def test_miura_folds_by_its_closed_form():
    n = 4
    p = orikin.generate("miura", rows=n, cols=n, width=MIURA_A, height=MIURA_B, angle=math.degrees(MIURA_GAMMA))
    classes = p.to_fold()["orikin:edges_class"]
    vid = lambda i, j: j * (n + 1) + i  # noqa: E731 (docs/generators.md)
    drive = p.edge(tuple((p.vertices[vid(2, 2)][:2] + p.vertices[vid(2, 3)][:2]) / 2))
    assert classes[drive] == "zigzag"
    sign = 1 if p.assignment[drive] == "V" else -1
    m = p.fold(fix=0, drive=drive, to=sign * 170, step=17)
    assert m.valid and m.frame_count == 11 and m.dof == 1
    edges = p.edges
    edge_of = {frozenset(map(int, e)): k for k, e in enumerate(edges)}
    cg = math.cos(MIURA_GAMMA)
    a, b, g = MIURA_A, MIURA_B, MIURA_GAMMA
    for k in range(1, m.frame_count):
        ang, pos = m.angles[k], m.vertices[k]
        for j in range(1, n):
            for i in range(1, n):
                v = vid(i, j)
                zu, zd = edge_of[frozenset((v, vid(i, j + 1)))], edge_of[frozenset((v, vid(i, j - 1)))]
                sl, sr = edge_of[frozenset((v, vid(i - 1, j)))], edge_of[frozenset((v, vid(i + 1, j)))]
                assert classes[zu] == classes[zd] == "zigzag" and classes[sl] == classes[sr] == "straight"
                # The zigzag pair folds equally; each straight crease |tan(ρs/2)| = cos γ |tan(ρz/2)|.
                assert ang[zu] == pytest.approx(ang[zd], abs=1e-9)
                tz = abs(math.tan(ang[zu] / 2))
                assert abs(math.tan(ang[sl] / 2)) == pytest.approx(cg * tz, abs=1e-9 * (1 + tz))
                assert abs(math.tan(ang[sr] / 2)) == pytest.approx(cg * tz, abs=1e-9 * (1 + tz))
                # Schenk & Guest 2013: the cell at θ = |ρz|/2.
                th = abs(ang[zu]) / 2
                u1, u2 = pos[vid(i, j + 1)] - pos[v], pos[vid(i, j - 1)] - pos[v]
                nrm = np.cross(u1, u2)
                nrm /= np.linalg.norm(nrm)
                s = pos[vid(i + 1, j)] - pos[v]
                H = abs(s @ nrm)
                sh = s - nrm * (s @ nrm)
                L = np.linalg.norm(sh)
                yh = sh / L
                xh = np.cross(nrm, yh)
                V, S = abs(u1 @ yh), abs(u1 @ xh)
                root = math.sqrt(1 + (math.cos(th) * math.tan(g)) ** 2)
                assert H == pytest.approx(a * math.sin(th) * math.sin(g), abs=1e-9)
                assert L == pytest.approx(a * math.sqrt(1 - (math.sin(th) * math.sin(g)) ** 2), abs=1e-9)
                assert S == pytest.approx(b * math.cos(th) * math.tan(g) / root, abs=1e-9)
                assert V == pytest.approx(b / root, abs=1e-9)


@pytest.mark.parametrize("args,kw", [
    ("--fix 0 --percent 100", dict(fix=0, percent=100)),
    ("--fix 0 --percent 50 --symmetric", dict(fix=0, percent=50, symmetric=True)),
    ("--fix 0 --drive 8 --to -90 --lock auto", dict(fix=0, drive=8, to=-90, lock="auto")),
    ("--fix 0 --drive 8 --to -90 --symmetric", dict(fix=0, drive=8, to=-90, symmetric=True)),
])
def test_the_modes_for_several_degrees_of_freedom_are_the_clis(args, kw):
    p = orikin.Pattern.load(repo("tests/data/waterbomb-base.fold"))
    m = p.fold(**kw)
    j = json.loads(cli(f"fold tests/data/waterbomb-base.fold {args} --json").stdout)
    assert m.verdict == j["verdict"] and m.reason == j["reason"] and m.locked == j["locked"]
    assert m.frame_count == len(j["frames"]) > 1
    for k, fr in enumerate(j["frames"]):
        want = fr["progress"] if "progress" in fr else math.radians(fr["drive_deg"])  # one drive: lock auto, then the fold
        assert m.drives[k] == pytest.approx(want, abs=1e-12)
        assert np.degrees(m.angles[k]) == pytest.approx(fr["fold_angles_deg"], abs=1e-9)
    assert m.residuals.max() <= 1e-10


def test_toward_the_targets_reaches_them():
    p = orikin.Pattern.load(repo("tests/data/waterbomb-base.fold"))
    m = p.fold(fix=0, percent=100)
    assert m.verdict == "reached" and m.valid and m.kind == "targets"
    assert np.degrees(m.angles[-1]) == pytest.approx(p.targets, abs=1e-7)
    assert all(c["fraction"] == pytest.approx(1.0, abs=1e-7) for c in m.creases)
    # Between frames: interpolated and closed onto the loop-closure manifold.
    s = m.at(0.37)
    assert orikin.Pattern.state(p, np.degrees(s.angles), fix=0).angles == pytest.approx(s.angles, abs=1e-9)


def test_several_drives_and_ratio():
    p = orikin.Pattern.load(repo("tests/data/waterbomb-base.fold"))
    under = p.fold(fix=0, drive=[8, 9], to=[-90, -90])
    assert under.verdict == "underdetermined" and "3 more degrees of freedom" in under.reason
    both = p.fold(fix=0, drive=[8, 9], to=-90, ratio=[1, 1], lock="auto")
    j = json.loads(cli("fold tests/data/waterbomb-base.fold --fix 0 --drive 8,9 --to -90 --ratio 1,1 --lock auto --json").stdout)
    assert both.verdict == j["verdict"] and both.locked == j["locked"]
    assert np.degrees(both.angles[-1]) == pytest.approx(j["frames"][-1]["fold_angles_deg"], abs=1e-9)


def test_a_fold_that_collides_stops_at_the_last_clean_step():
    p = orikin.Pattern.load(repo("examples/patterns/two-flaps.fold"))
    m = p.fold(frame=1, fix=1, drive=8, lock=[7], to=180)
    r = cli("fold examples/patterns/two-flaps.fold --frame 1 --fix 1 --drive 8 --lock 7 --to 180")
    assert m.verdict == "collision" and not m.valid
    assert m.collision.faces == (0, 2) and m.collision.kind == "penetrating"
    assert math.degrees(m.collision.drive_rad) == pytest.approx(131.81031, abs=1e-5)
    assert f"verdict: collision: {m.reason}" in r.stdout
    assert m.frame_count == m.collision.frame == 14 and m.angles.shape[0] == 14
    unchecked = p.fold(frame=1, fix=1, drive=8, lock=[7], to=180, collisions=False)
    assert unchecked.verdict == "valid" and unchecked.frame_count > 14


def test_progress_reports_monotone_fractions_and_false_cancels():
    open_corner = load_open_corner()
    seen = []
    m = open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, step=10, progress=seen.append)
    assert m.valid and seen and seen[-1] == pytest.approx(1.0) and seen == sorted(seen)
    with pytest.raises(orikin.Cancelled) as e:
        open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, step=10, progress=lambda f: f < 0.5)
    assert "cancelled" in str(e.value) and e.value.status == "ERR_LIMIT"

    class Stop(Exception):
        pass

    def boom(f):
        raise Stop(f)

    with pytest.raises(Stop):  # the callback's own exception comes through
        open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, progress=boom)
    with pytest.raises(TypeError):
        open_corner.fold(fix=T2, drive=DIAG, lock=[DOWN], to=180, progress=3)


def test_the_gil_is_released_while_solving():
    # A fold of a 40 × 40 Miura-ori in 1° steps; meanwhile another thread keeps running Python.
    # With the GIL held the other thread would stall for the whole solve.
    p = orikin.generate("miura", rows=40, cols=40)
    drive = p.edge(tuple((p.vertices[20 * 41 + 20][:2] + p.vertices[21 * 41 + 20][:2]) / 2))
    sign = 1 if p.assignment[drive] == "V" else -1
    done, gaps = threading.Event(), []
    result = {}

    def solve():
        t0 = time.perf_counter()
        result["m"] = p.fold(fix=0, drive=drive, to=sign * 150, step=0.5, collisions=False)
        result["t"] = time.perf_counter() - t0
        done.set()

    th = threading.Thread(target=solve)
    last = time.perf_counter()
    th.start()
    ticks = 0
    while not done.is_set():
        now = time.perf_counter()
        gaps.append(now - last)
        last = now
        ticks += 1
        time.sleep(0.001)
    th.join()
    assert result["m"].valid
    assert ticks > 10, f"{ticks} ticks in {result['t']:.3f} s: the solve held the GIL"
    assert max(gaps) < 0.5 * result["t"] + 0.05, (max(gaps), result["t"])
