"""motion.angles, motion.vertices, record.angles, record.vertices: numpy arrays that view the
library's memory — no copy, read-only, and alive as long as an array needs them."""

import gc
import weakref

import numpy as np
import pytest

import orikin
from orikin import _orikin
from conftest import open_corner, repo


def solved():
    return open_corner().fold(fix=4, drive=12, lock=[11], to=180, step=30)


def test_the_arrays_view_the_librarys_block_without_copying():
    m = solved()
    a1, a2 = m.angles, m.angles
    assert not a1.flags.owndata and a1.base is m._m  # the Motion object owns the memory
    assert a1.ctypes.data == a2.ctypes.data and np.shares_memory(a1, a2)
    v1, v2 = m.vertices, m.vertices
    assert not v1.flags.owndata and v1.base is m._m and v1.ctypes.data == v2.ctypes.data
    # The per-frame rows are the library's frames: stride = (E + 1) doubles (ori_motion_angles).
    assert a1.strides[1] == 8 and a1.strides[0] >= 13 * 8
    assert v1.shape == (m.frame_count, 9, 3) and v1.flags.c_contiguous
    # The views hold what the solver wrote: a state's vertices are the mechanism's posed ones.
    s = m.pattern.state(np.degrees(a1[-1]), fix=4)
    assert s.positions == pytest.approx(v1[-1], abs=1e-12)


def test_writing_is_refused_and_cannot_be_switched_on():
    m = solved()
    for arr in (m.angles, m.vertices):
        assert not arr.flags.writeable
        with pytest.raises(ValueError, match="read-only"):
            arr[0, 0] = 1.0
        with pytest.raises(ValueError):
            arr.flags.writeable = True
        with pytest.raises(ValueError):
            np.add(arr, 1, out=arr)
    # A copy is the user's own.
    c = m.angles.copy()
    c[0, 0] = 1.0
    assert m.angles[0, 0] == 0.0


def test_an_array_keeps_the_motion_alive_after_its_owners_are_gone():
    base = _orikin._alloc_live_count()
    m = solved()
    angles, vertices = m.angles, m.vertices
    want_a, want_v = angles.copy(), vertices.copy()
    probe = weakref.ref(m._m)
    del m
    gc.collect()
    # The Python Motion and Pattern are gone; the library's motion lives on for the arrays.
    assert probe() is not None
    assert _orikin._alloc_live_count() > base
    junk = [solved() for _ in range(3)]  # reuse freed memory, if it had been freed
    del junk
    gc.collect()
    assert np.array_equal(angles, want_a) and np.array_equal(vertices, want_v)
    del angles
    gc.collect()
    assert probe() is not None  # the vertices still hold it
    assert np.array_equal(vertices, want_v)
    del vertices
    gc.collect()
    assert probe() is None and _orikin._alloc_live_count() == base


def test_slices_and_frame_states_hold_the_motion_too():
    m = solved()
    row = m.angles[3]
    state = m.frame(-1)
    probe = weakref.ref(m._m)
    want = row.copy()
    del m
    gc.collect()
    assert probe() is not None and np.array_equal(row, want)
    assert state.angles.base is not None and not state.angles.flags.writeable
    del row, state
    gc.collect()
    assert probe() is None


def test_a_record_views_its_states_the_same_way():
    r = orikin.Record.load(repo("examples/open-corner.seq.json"))
    a, v = r.angles, r.vertices
    assert a.base is r._r and v.base is r._r and not a.flags.writeable and not v.flags.writeable
    assert a.shape == (r.frame_count, 13) and v.shape == (r.frame_count, 9, 3)
    with pytest.raises(ValueError):
        a[0, 0] = 1
    probe = weakref.ref(r._r)
    want = a.copy()
    del r
    gc.collect()
    assert probe() is not None and np.array_equal(a, want)
    del a, v
    gc.collect()
    assert probe() is None


def test_no_frames_give_empty_views():
    m = open_corner().fold(fix=4, drive=12, to=90)  # underdetermined: no frames
    assert m.angles.shape == (0, 13) and m.vertices.shape == (0, 9, 3)
