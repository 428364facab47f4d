"""The design-search step (DesignEnv): add a crease, get rigid foldability, DOF and collision."""

import math

import numpy as np
import pytest

import orikin


def env(**kw):
    return orikin.DesignEnv(orikin.Pattern.square(4), **kw)


def test_one_valley_across_the_sheet_folds_flat_with_one_degree_of_freedom():
    e = env()
    r = e.step({"line": ((0, 0), (4, 4)), "assignment": "V"})
    assert r.applied and r.error is None and len(r.edges) == 1 and r.creases == 1
    assert r.rigid_foldable and r.verdict == "reached" and r.progress == pytest.approx(1.0)
    assert r.dof == 1 and not r.collides and r.collision_checked
    assert r.reward == 1.0 and not r.terminated and not r.truncated
    assert e.pattern.edge_count == 5 and e.pattern.assignment.count("V") == 1
    obs, reward, terminated, truncated, info = r.astuple()
    assert obs is e.pattern and reward == 1.0 and info["dof"] == 1


def test_the_judgement_is_the_librarys_own():
    e = env()
    e.step({"line": ((0, 0), (4, 4)), "assignment": "V"})
    r = e.step({"axiom": 2, "p1": (0, 0), "p2": (4, 4), "assignment": "M"})  # the other diagonal
    assert r.applied and r.creases == 4 and e.pattern.interior_vertex_count == 1
    dof = e.pattern.dof()
    assert r.dof == dof.generic_dof and r.flat_dof == dof.dof
    m = e.pattern.fold(percent=100, collisions=False)
    assert r.verdict == m.verdict and r.progress == pytest.approx(float(m.drives[-1]), abs=1e-12)
    assert r.rigid_foldable == (m.frame_count >= 2 and not m.violations)


def test_a_degree_three_vertex_is_rigid_and_ends_the_episode():
    e = env()
    centre = (2.0, 2.0)
    for k in range(3):
        a = math.radians(90 + 120 * k)
        far = (2 + 3 * math.cos(a), 2 + 3 * math.sin(a))
        r = e.step({"line": (centre, far), "segment": True, "assignment": "V"})
        assert r.applied
    assert e.pattern.interior_vertex_count == 1
    assert not r.rigid_foldable and r.dof == 0 and r.terminated and r.reward == -1.0


def test_two_flaps_folding_onto_each_other_collide():
    e = env()
    e.step({"line": ((1.5, 0), (1.5, 4)), "assignment": "V"})
    r = e.step((2.5, 0, 2.5, 4))  # a 4-sequence: the line through two points, the env's assignment (V)
    assert r.applied and r.dof == 2 and r.collides and r.collision["faces"]
    assert r.terminated and r.reward == -1.0
    quiet = orikin.DesignEnv(orikin.Pattern.square(4), collisions=False)
    quiet.step({"line": ((1.5, 0), (1.5, 4))})
    assert not quiet.step((2.5, 0, 2.5, 4)).collides


def test_a_crease_that_misses_leaves_the_pattern_and_says_why():
    e = env()
    before = e.pattern
    r = e.step({"line": ((5, 0), (5, 4))})
    assert not r.applied and r.error == "the crease does not cross the sheet"
    assert e.pattern is before and r.reward == -1.0 and not r.terminated
    none = e.step({"axiom": 5, "p1": (0, 0), "p2": (0.1, 0.1), "l1": ((10, 10), (1, 0)), "solution": 1})
    assert not none.applied


def test_reset_truncation_and_a_custom_reward():
    e = env(max_creases=2, reward=lambda r: r.dof or 0)
    e.step({"line": ((1, 0), (1, 4))})
    r = e.step({"line": ((3, 0), (3, 4))})
    assert r.truncated and r.reward == 2
    assert e.reset() is e.sheet and e.pattern.edge_count == 4 and e.history == []


def test_steps_keep_the_library_balanced_and_patterns_immutable():
    e = env()
    rng = np.random.default_rng(5)
    pts = [(float(x), float(y)) for x in range(5) for y in range(5)]
    seen = []
    for _ in range(40):
        i, j = rng.choice(len(pts), 2, replace=False)
        r = e.step({"line": (pts[i], pts[j]), "assignment": "MV"[rng.integers(2)]})
        seen.append(r.pattern)
        if r.terminated:
            e.reset()
    counts = [p.edge_count for p in seen]
    assert counts == [p.edge_count for p in seen]  # a later step never changes an earlier pattern
