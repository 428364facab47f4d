"""check (local flat-foldability), regularize, dof and layers (global flat-foldability)."""

import json
import math

import numpy as np
import pytest

import orikin
from conftest import cli, open_corner, repo, shared


def single_vertex(sectors_deg, assignment="U"):
    """A vertex at the origin with creases at the given sector angles, on a polygon sheet."""
    angles = np.radians(np.cumsum([0.0] + list(sectors_deg[:-1])))
    n = len(angles)
    verts = [(0.0, 0.0)] + [(math.cos(a), math.sin(a)) for a in angles]
    edges = [(0, k + 1) for k in range(n)] + [(k + 1, (k + 1) % n + 1) for k in range(n)]
    return orikin.Pattern.from_arrays(verts, edges, assignment * n + "B" * n)


def test_hulls_count_is_the_reference_value():
    # SPEC item 3: C(100, 70, 50, 40, 30, 70) = 8, as `orikin mv-count` says.
    p = single_vertex([100, 70, 50, 40, 30, 70])
    (v,) = p.check().vertices
    assert v.mv_count == 8 == int(cli("mv-count 100 70 50 40 30 70").stdout.split()[-1])
    assert v.kawasaki and v.degree == 6 and v.completions == 8 and v.maekawa is None  # U creases: undetermined
    assert v.sectors_rad == pytest.approx(np.radians([100, 70, 50, 40, 30, 70]), abs=1e-12)


def test_check_reports_what_the_cli_reports():
    for path in ("examples/patterns/degree4-vertex.fold", "examples/patterns/non-flat-foldable-vertex.fold",
                 "tests/data/rounded-miura.fold"):
        c = orikin.Pattern.load(repo(path)).check()
        j = json.loads(cli(f"check {path} --json").stdout)
        assert c.flat_foldable == j["locally_flat_foldable"]
        assert (c.interior_count, c.failed_count) == (j["interior_vertices"], j["failed_vertices"])
    bad = orikin.Pattern.load(repo("examples/patterns/non-flat-foldable-vertex.fold")).check()
    assert not bad.flat_foldable and bad.violations and bad.violations[0].detail
    assert {v.rule for v in bad.violations} <= {"kawasaki", "maekawa", "big_little_big", "assignment", "cone"}


def test_a_rounded_drawing_passes_within_tolerance_and_regularizes_to_an_exact_rigid_pattern():
    p = orikin.Pattern.load(repo("tests/data/rounded-miura.fold"))
    assert not p.check().flat_foldable
    within = p.check(tolerance=0.01)
    assert within.flat_foldable and within.within_count == 5
    assert math.degrees(within.max_deviation_rad) == pytest.approx(0.00694, abs=5e-6)
    r = p.regularize(rigid=True)
    j = json.loads(cli("regularize tests/data/rounded-miura.fold --rigid --json -o /dev/null").stdout)
    assert r.converged and r.pattern is not None and r.mode_vertices == 6
    assert r.max_move_rel == pytest.approx(j["max_move_rel"], rel=1e-9)
    assert r.pattern.check().flat_foldable and r.kawasaki_after_rad <= 1e-12
    # The regularized pattern folds toward its targets and keeps the file's other fields.
    m = r.pattern.fold(percent=50)
    assert m.frame_count > 1 and m.residuals.max() <= 1e-10
    assert r.pattern.to_fold().keys() >= p.to_fold().keys() - {"faces_edges", "edges_faces", "vertices_vertices"}


def test_dof_of_the_open_corner_is_the_clis():
    d = open_corner().dof()
    j = json.loads(cli("dof examples/patterns/open-corner.fold --json").stdout)
    assert (d.grubler, d.rank, d.dof, d.generic_dof) == (j["grubler"], j["rank"], j["dof"], j["generic_dof"]) == (-1, 2, 3, 2)
    assert d.singular and not d.rigid
    # Locking the down crease leaves the one degree of freedom the first fold uses.
    assert open_corner().dof(lock=[11]).generic_dof == 1
    # At a folded state (a State from a fold), the state is regular.
    m = open_corner().fold(fix=4, drive=12, lock=[11], to=90)
    at = open_corner().dof(m.frame(-1))
    assert at.dof == at.generic_dof == 2 and not at.singular


def test_miura_has_one_degree_of_freedom():
    d = orikin.generate("miura", rows=4, cols=4).dof()
    assert d.generic_dof == 1 and d.singular


@pytest.mark.parametrize("path,count", [("examples/patterns/degree6-vertex.fold", 2),
                                        ("examples/patterns/degree4-vertex.fold", 1),
                                        ("tests/data/layers/pleat-unassigned.fold", 16)])
def test_layer_counts_are_the_clis(path, count):
    L = orikin.Pattern.load(repo(path)).layers()
    assert L.count == count == int(cli(f"layers {path} --count").stdout.strip())
    assert L.satisfiable and L.conflict is None and not L.limited
    prod = 1
    for states, _ in L.components:
        prod *= states
    assert prod == count


def test_a_layer_state_as_face_orders_a_drawing_and_a_folded_frame():
    p = orikin.Pattern.load(repo("examples/patterns/degree6-vertex.fold"))
    L = p.layers()
    s0, s1 = L.state(0), L.state(1)
    assert s0.face_orders.shape == (L.info().variables, 3) and not np.array_equal(s0.face_orders, s1.face_orders)
    assert set(np.abs(s0.face_orders[:, 2])) == {1} and s0.svg.startswith("<?xml")
    fold = s1.to_fold()
    assert len(fold["file_frames"]) == 1 and "foldedForm" in fold["file_frames"][0]["frame_classes"]
    with pytest.raises(orikin.InputError) as e:
        L.state(2)
    assert e.value.option == "--state"


def test_flat_folders_published_counts_are_exact_integers():
    for rel, count, comps in (("flat-folder/instagram_002_traditional_Kabuto.fold", 9, [1, 3, 3]),
                              ("flat-folder/instagram_043_ku_Quad_Overlap.fold", 65536, [1] + [2] * 16)):
        L = orikin.Pattern.load(shared(rel)).layers()
        assert L.count == count and [c for c, _ in L.components] == comps


def test_no_state_names_the_conflict():
    L = orikin.Pattern.load(shared("flat-folder/unsatisfiable_001_ku_Bad_Twist.fold")).layers()
    assert L.count == 0 and not L.satisfiable and L.conflict.detail


def test_layers_progress_can_cancel():
    p = orikin.Pattern.load(repo("tests/data/layers/pleat-unassigned.fold"))
    calls = []
    L = p.layers(progress=lambda f: calls.append(f))
    assert L.count == 16
    with pytest.raises(orikin.Cancelled):
        p.layers(progress=lambda f: False)
