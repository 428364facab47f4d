"""The compliant fold (Pattern.fold(compliant=True); `orikin fold --compliant`, docs/compliant.md):
the same numbers as the CLI, convergence to the exact rigid fold as the panels stiffen, and the
CLI's messages for bad arguments."""

import json
import math

import numpy as np
import pytest

import orikin
from conftest import cli, cli_error, open_corner, repo


def test_open_corner_agrees_with_the_cli_json():
    p = open_corner()
    f = p.fold(compliant=True, percent=40)
    assert isinstance(f, orikin.CompliantFold)
    r = cli("fold examples/patterns/open-corner.fold --compliant --percent 40 --json")
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert f.reached and j["reached"]
    assert f.reached_fraction == pytest.approx(0.4, abs=1e-15)
    for key in ("max_strain", "energy", "crease_error_deg", "gradient_norm", "load_scale"):
        assert f[key] == pytest.approx(j[key], rel=1e-9, abs=1e-12), key
    for key in ("vertices", "bars", "hinges", "newton_iterations", "load_steps"):
        assert f[key] == j[key], key
    np.testing.assert_allclose(f.fold_angles_deg, j["fold_angles_deg"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(f.strains, j["strains"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(f.face_energies, j["face_energies"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(f.face_strains, j["face_strains"], rtol=1e-9, atol=1e-15)
    assert f.face_energies.shape == (p.face_count,) and f.face_strains.max() == pytest.approx(f.max_strain, rel=1e-12)
    info = f.info()
    assert info["model"] == "compliant" and info["solver"] == "static" and info["percent"] == 40.0
    assert set(info) <= set(j) | {"file"} and set(j) - set(info) <= {"file"}
    # the creases folded toward their targets (valleys up, mountains down) and the state is a
    # real equilibrium
    assert f.gradient_norm <= 1e-10 * f.load_scale
    assert f.positions.shape == (p.vertex_count, 3)
    assert np.all(np.isfinite(f.positions))
    targets = p.targets
    creases = [e for e, a in enumerate(p.assignment) if a in "MV"]
    for e in creases:
        assert np.sign(f.fold_angles[e]) == np.sign(targets[e]), e


def test_dynamic_agrees_with_the_cli_json():
    p = open_corner()
    f = p.fold(compliant=True, percent=30, dynamic=True, steps=200000)
    r = cli("fold examples/patterns/open-corner.fold --compliant --percent 30 --dynamic --steps 200000 --json")
    j = json.loads(r.stdout)
    assert f.solver == "explicit" and f.steps == j["steps"] and f.reached == j["reached"]
    assert f.time_step == pytest.approx(j["time_step"], rel=1e-12)
    np.testing.assert_allclose(f.fold_angles_deg, j["fold_angles_deg"], rtol=0, atol=1e-9)
    # the settled explicit state is the static equilibrium
    s = p.fold(compliant=True, percent=30)
    np.testing.assert_allclose(f.fold_angles, s.fold_angles, rtol=0, atol=1e-5)


def test_the_explicit_time_history(tmp_path):
    # with all_frames the explicit solver keeps its history: the flat start, evenly spaced times
    # (a multiple of the time step), the settled end; the CLI writes it as frame_time
    p = open_corner()
    f = p.fold(compliant=True, dynamic=True, percent=40, all_frames=True)
    t = f.frame_times
    assert 3 <= len(t) <= 257 and t[0] == 0.0
    assert np.all(np.diff(t) > 0)
    assert t[-1] == pytest.approx(f.steps * f.time_step, rel=1e-12)
    np.testing.assert_array_equal(f.frame_angles[-1], f.fold_angles)
    np.testing.assert_allclose(f.frame_positions[0][:, 2], 0.0, atol=0)  # the flat sheet
    out = tmp_path / "dyn.fold"
    cli(f"fold examples/patterns/open-corner.fold --compliant --dynamic --percent 40 --all-frames -o {out}")
    frames = json.load(open(out))["file_frames"]
    np.testing.assert_allclose([fr["frame_time"] for fr in frames], t, rtol=0, atol=0)


def test_all_frames_and_options_reach_the_model():
    p = open_corner()
    f = p.fold(compliant=True, percent=40, all_frames=True, axial=200, facet=2, crease=0.7, fix=4)
    assert f.frame_positions.shape == (len(f.frame_fractions), p.vertex_count, 3)
    assert f.frame_angles.shape == (len(f.frame_fractions), p.edge_count)
    assert np.all(np.diff(f.frame_fractions) > 0) and f.frame_fractions[-1] == pytest.approx(0.4, abs=1e-15)
    np.testing.assert_array_equal(f.frame_angles[-1], f.fold_angles)
    r = cli("fold examples/patterns/open-corner.fold --compliant --percent 40 --axial 200 --facet 2 --fix 4 --json")
    j = json.loads(r.stdout)
    np.testing.assert_allclose(f.fold_angles_deg, j["fold_angles_deg"], rtol=0, atol=1e-9)
    # stiffer panels strain less than the default ones
    assert f.max_strain < p.fold(compliant=True, percent=40, fix=4).max_strain
    # the fixed face's vertices stay where the flat sheet has them
    fixed = p.faces[4]
    np.testing.assert_allclose(f.positions[fixed, :2], p.vertices[fixed, :2], atol=1e-12)
    np.testing.assert_allclose(f.positions[fixed, 2], 0.0, atol=1e-12)
    st = f.state()
    assert st.positions.shape == (p.vertex_count, 3)
    assert f.export(format="obj").startswith(b"#") or b"v " in f.export(format="obj")


def _drive_of_face0(p):
    face = set(p.faces[0])
    for e, (a, b) in enumerate(p.edges):
        if p.assignment[e] in "MV" and a in face and b in face:
            return e
    raise AssertionError("face 0 has no crease")


def test_miura_converges_to_the_rigid_fold():
    """As in tests/test_compliant.c: facet and axial stiffness raised over the crease stiffness,
    the compliant angles approach orikin's exact rigid fold at the same drive (error ~ 1/ratio)."""
    p = orikin.generate("miura")
    drive = _drive_of_face0(p)
    creases = [e for e, a in enumerate(p.assignment) if a in "MV"]
    errors = []
    for dec in (2, 4, 6):
        ratio = 10.0 ** dec
        f = p.fold(compliant=True, percent=50, fix=0, axial=20 * ratio, facet=0.2 * ratio)
        assert f.reached
        m = p.fold(fix=0, drive=drive, to=math.degrees(f.fold_angles[drive]), collisions=False)
        assert m.valid, m.verdict
        err = np.max(np.abs(f.fold_angles[creases] - m.angles[-1, creases]))
        errors.append(math.degrees(err))
    # the error falls as 1/stiffness: 100x per two decades (docs/compliant.md's table)
    assert errors[0] > errors[1] > errors[2]
    assert errors[0] / errors[1] == pytest.approx(100, rel=0.1)
    assert errors[1] / errors[2] == pytest.approx(100, rel=0.1)
    assert errors[2] <= 1e-3


def test_errors_are_the_clis(monkeypatch):
    monkeypatch.chdir(repo("."))
    src = "examples/patterns/open-corner.fold"
    p = orikin.Pattern.load(src)
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, fix=99)
    assert str(e.value) == cli_error(f"fold {src} --compliant --fix 99")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, fix=(5.0, 5.0))
    assert str(e.value) == cli_error(f"fold {src} --compliant --fix @5,5")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, axial=0)
    assert str(e.value) == cli_error(f"fold {src} --compliant --axial 0")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, percent=120)
    assert str(e.value) == cli_error(f"fold {src} --compliant --percent 120")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, preset="paper")
    assert str(e.value) == cli_error(f"fold {src} --compliant --preset paper")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, drive=3)
    assert str(e.value) == cli_error(f"fold {src} --compliant --drive 3")
    with pytest.raises(orikin.InputError) as e:
        p.fold(compliant=True, dynamic=True, threads=0)
    assert str(e.value) == cli_error(f"fold {src} --compliant --dynamic --threads 0")
    with pytest.raises(orikin.InputError, match="--dynamic is an option of the compliant fold"):
        p.fold(fix=4, drive=12, to=10, dynamic=True)
    with pytest.raises(orikin.InputError, match="--threads is an option of the compliant fold"):
        p.fold(fix=4, drive=12, to=10, threads=2)


def test_contact_warnings_are_the_clis(tmp_path):
    """The open corner at 100 %: the compliant sheet's faces pass through each other (the CLI
    warns of each pair on stderr and lists them in --json); at 40 % they do not."""
    p = open_corner()
    f = p.fold(compliant=True)
    j = json.loads(cli("fold examples/patterns/open-corner.fold --compliant --json").stdout)
    assert [list(c["faces"]) for c in f.contacts] == [c["faces"] for c in j["contacts"]]
    assert [c["step"] for c in f.contacts] == [c["step"] for c in j["contacts"]]
    assert len(f.contacts) >= 1
    for c in f.contacts:
        a, b = c["faces"]
        assert 0 <= a < b < p.face_count and 0 < c["fraction"] <= 1
    r = cli("fold examples/patterns/open-corner.fold --compliant")
    warned = [l for l in r.stderr.splitlines() if "pass through each other" in l]
    assert len(warned) == len(f.contacts)
    a, b = f.contacts[0]["faces"]
    assert f"faces {a} and {b} pass through each other at load step {f.contacts[0]['step']}" in warned[0]
    assert p.fold(compliant=True, percent=40).contacts == []
