"""Fold sequences (the folding manager) and actuation: hinge sizing and folding dynamics."""

import json
import math

import numpy as np
import pytest

import orikin
from conftest import cli, open_corner, repo


def test_the_open_corner_sequence_restores_any_instant_as_the_cli():
    r = orikin.Record.load(repo("examples/open-corner.seq.json"))
    assert r.valid and r.verdict == "valid" and r.completed_folds == 2 and r.duration == 2.0
    assert r.times[0] == 0.0 and r.times[-1] == 2.0 and np.all(np.diff(r.times) > 0)
    assert set(r.folds.tolist()) == {0, 1}
    s = r.at(1.5)
    j = json.loads(cli("sequence examples/open-corner.seq.json --at 1.5 --json").stdout)
    assert s.drive == pytest.approx(math.radians(j["drive_deg"]), abs=1e-12)
    assert np.degrees(s.angles) == pytest.approx(j["fold_angles_deg"], abs=1e-9)
    assert s.positions == pytest.approx(np.array(j["vertices_coords"]), abs=1e-12)
    # The corner cube at the end: the three squares mutually perpendicular (crease 11 at 90°).
    end = r.at(2.0)
    assert math.degrees(end.angles[11]) == pytest.approx(90, abs=1e-9)
    assert math.degrees(end.angles[12]) == pytest.approx(180, abs=1e-9)
    with pytest.raises(orikin.InputError) as e:
        r.at(3.0)
    assert e.value.option == "--at" and str(e.value).startswith("--at: ")


def test_a_sequence_from_python_folds_is_the_files():
    folds = json.load(open(repo("examples/open-corner.seq.json")))["folds"]
    mine = open_corner().sequence(folds)
    theirs = orikin.Record.load(repo("examples/open-corner.seq.json"))
    assert np.array_equal(mine.angles, theirs.angles) and np.array_equal(mine.vertices, theirs.vertices)
    assert json.loads(mine.to_json())["folds"][1]["drive"] == 11
    fold = mine.to_fold()
    assert len(fold["file_frames"]) == mine.frame_count
    # Names and points resolve as in SEQ.json; a bad one says where.
    named = open_corner().sequence([{"fix": "Obj1212", "drive": "@0.5,0.5", "lock": ["@1,0.5"], "to": 90}])
    assert named.valid and math.degrees(named.angles[-1, 9]) == pytest.approx(60, abs=1e-9)
    with pytest.raises(orikin.InputError) as e:
        open_corner().sequence([{"fix": "Obj9", "drive": 12, "to": 90}])
    assert "folds" in str(e.value) and "Obj9" in str(e.value)


def test_a_failing_fold_stops_the_sequence():
    r = orikin.Record.load(repo("tests/data/kin-first-fold-invalid.seq.json"))
    j = json.loads(cli("sequence tests/data/kin-first-fold-invalid.seq.json --json").stdout)
    assert not r.valid and r.failed_fold == 0 and r.verdict == j["verdict"]


def test_thesis_flap_needs_ten_milliamps():
    # 20 mA in 0.1 T folds the 500 µm flap to 180° (SPEC item 12); the optimised schedule needs
    # 10.12 mA, as `orikin actuate` reports.
    flap = orikin.Pattern.load(repo("examples/patterns/thesis-flap.fold"))
    a = flap.fold(fix=0, drive=0, to=180).actuate()
    j = json.loads(cli("actuate examples/patterns/thesis-flap.fold --fix 0 --drive 0 --to 180 --json").stdout)
    assert a.feasible and a.current_needed_a == pytest.approx(j["current_needed"], rel=1e-12)
    assert a.current_needed_a * 1e3 == pytest.approx(10.12, abs=0.005)
    (h,) = a.hinges
    # M_p = ¼ σ_y w t² for gold, 10 µm × 0.6 µm: 1.854e-10 N·m (the thesis' M_req).
    assert h.mechanics["plastic_moment_nm"] == pytest.approx(0.25 * 206e6 * 10e-6 * 0.6e-6 ** 2, rel=1e-12)
    assert math.degrees(h.springback_rad) == pytest.approx(j["hinges"][0]["springback_deg"], rel=1e-12)
    assert len(a.schedule) == 2 and a.reorientations == 1
    assert a.steps["current_a"].shape == (1, 19) and a.steps["current_a"].max() == pytest.approx(a.current_needed_a)
    # A fixed field needs more current than the optimised one.
    fixed = flap.fold(fix=0, drive=0, to=180).actuate(schedule="fixed")
    assert fixed.current_needed_a > a.current_needed_a


def test_the_flap_folds_in_time_and_latches_where_the_cli_says():
    flap = orikin.Pattern.load(repo("examples/patterns/thesis-flap.fold"))
    # The CLI optimises the field along the quasi-static fold (5° steps) first; so do we.
    schedule = flap.fold(fix=0, drive=0, to=180, step=5).actuate().schedule
    sim = flap.simulate(fix=0, current=0.02, duration=0.006, schedule=schedule)
    j = json.loads(cli("simulate examples/patterns/thesis-flap.fold --fix 0 --current 0.02 --duration 0.006 --json").stdout)
    assert sim.reached_target and sim.time_to_target_s == pytest.approx(j["time_to_target"], rel=1e-12)
    assert math.degrees(sim.latched_rad[0]) == pytest.approx(j["latched_angle_deg"][0], abs=1e-9)
    assert sim.angles.shape == (101, 7) and sim.vertices.shape[0] == 101 and sim.times[-1] == pytest.approx(0.006)
    assert sim.max_residual <= 1e-10 and sim.energy_drift == pytest.approx(j["energy_drift"], rel=1e-6)


def test_actuation_needs_a_design():
    with pytest.raises(orikin.InputError):
        open_corner().fold(fix=4, drive=12, lock=[11], to=90).actuate()


def test_the_flap_on_compliant_panels_is_the_clis():
    # simulate --model compliant from Python: the same equilibria under 20 mA (gravity on, as
    # the file asks), the same plastic rotation and latched angle
    flap = orikin.Pattern.load(repo("examples/patterns/thesis-flap.fold"))
    sim = flap.simulate(model="compliant", fix=0, current=0.02)
    j = json.loads(cli("simulate examples/patterns/thesis-flap.fold --model compliant --fix 0 --current 0.02 --json").stdout)
    assert isinstance(sim, orikin.CompliantSimulation) and sim.wires == j["wires"] == 1
    for e in range(7):
        assert math.degrees(sim.loaded_rad[e]) == pytest.approx(j["loaded"]["angles_deg"][e], abs=1e-9)
        assert math.degrees(sim.plastic_rotation_rad[e]) == pytest.approx(j["loaded"]["plastic_rotation_deg"][e], abs=1e-9)
        assert math.degrees(sim.latched_rad[e]) == pytest.approx(j["latched_angle_deg"][e], abs=1e-9)
    assert sim.currents[0] == pytest.approx(j["loaded"]["currents"][0], rel=1e-15)
    assert sim.max_strain == pytest.approx(j["loaded"]["max_strain"], rel=1e-12)
    assert 60 < math.degrees(sim.loaded_rad[0]) < 90 and math.degrees(sim.latched_rad[0]) < math.degrees(sim.loaded_rad[0])
    assert sim.angles.shape == (len(j["frames"]), 7) and len(sim.current_fractions) == len(j["frames"])
    with pytest.raises(orikin.InputError, match="--duration is the rigid model's"):
        flap.simulate(model="compliant", fix=0, current=0.02, duration=0.01)
    with pytest.raises(orikin.InputError, match="--model is rigid or compliant"):
        flap.simulate(model="springy", fix=0, current=0.02)
    with pytest.raises(orikin.InputError, match="missing --duration"):
        flap.simulate(fix=0, current=0.02)
