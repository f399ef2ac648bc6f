# SPDX-License-Identifier: BSD-3-Clause
"""Every C handle is released exactly once: by close(), by a with block or
by the garbage collector; borrowed handles keep their owners alive and are
never released themselves; closing an owner closes what depends on it.
The destroy functions are wrapped to count what they release (the leak
and double-free oracle)."""
import collections
import gc

import pytest

from conftest import data

DESTROYS = ["projcurve_surface_destroy", "projcurve_curve_destroy", "projcurve_result_destroy",
            "projcurve_model_destroy", "projcurve_options_destroy", "projcurve_face_destroy",
            "projcurve_iges_writer_destroy", "projcurve_step_writer_destroy"]


@pytest.fixture
def released(pc, monkeypatch):
    """{destroy function: Counter of the pointers it released}."""
    counts = collections.defaultdict(collections.Counter)
    for name in DESTROYS:
        real = pc._lib.fn[name]

        def counting(ptr, real=real, name=name):
            counts[name][ptr] += 1
            real(ptr)
        monkeypatch.setitem(pc._lib.fn, name, counting)
    return counts


def make_all(pc, tmp_path):
    """One of each owned handle, plus borrowed ones; returns the pointers made."""
    s = pc.Surface.from_nurbs((1, 1), (2, 2), [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]],
                              ([0, 0, 1, 1], [0, 0, 1, 1]))
    c = pc.Curve.from_nurbs(1, [[0.1, 0.2, 2], [0.9, 0.7, 2]], [0, 0, 1, 1])
    o = pc.Options(tol_distance=1e-6)
    r = pc.project_directional(s, c, (0, 0, -1), o)
    cone = pc.project_conical(s, c, (0.5, 0.45, 20), o)
    b = r.branches[0]
    curves = [b.curve(), b.compact_curve(), b.compact_pcurve()]
    f = pc.Face.create(s)
    m = pc.Model.read(data("cases-brep", "shell_2x2.step"))
    borrowed = m.surfaces + m.faces + m.shapes[0].faces + [m.faces[0].surface]
    w = pc.IgesWriter()
    w.add_result(s, r)
    w.write(tmp_path / "x.igs")
    sw = pc.StepWriter()
    sw.add_result(s, cone)
    sw.write(tmp_path / "x.step")
    made = {"projcurve_surface_destroy": [s], "projcurve_curve_destroy": [c] + curves,
            "projcurve_result_destroy": [r, cone], "projcurve_options_destroy": [o],
            "projcurve_face_destroy": [f], "projcurve_model_destroy": [m],
            "projcurve_iges_writer_destroy": [w], "projcurve_step_writer_destroy": [sw]}
    ptrs = {k: [h._ptr for h in v] for k, v in made.items()}
    return made, ptrs, borrowed


def test_gc_releases_each_once(pc, released, tmp_path):
    made, ptrs, borrowed = make_all(pc, tmp_path)
    del made, borrowed
    gc.collect()
    for name, expected in ptrs.items():
        assert released[name] == collections.Counter(expected), name


def test_close_then_gc(pc, released, tmp_path):
    made, ptrs, borrowed = make_all(pc, tmp_path)
    for handles in made.values():
        for h in handles:
            h.close()
            h.close()  # twice: nothing more
            assert h.closed
    assert all(b.closed for b in borrowed)  # closing the model closed them
    del made, borrowed
    gc.collect()
    for name, expected in ptrs.items():
        assert released[name] == collections.Counter(expected), name


def test_with_blocks(pc, released):
    with pc.Model.read(data("cases", "bumpy_bicubic_8x8_down.igs")) as m:
        s, c = m.surfaces[0], m.curves[0]
        with pc.project_directional(s, c, (0, 0, -1), tol_distance=1e-3) as r:
            branch = r.branches[0]
        assert r.closed
        with pytest.raises(pc.NullArgumentError):
            branch.tuv()
    assert s.closed and c.closed and m.closed
    assert sum(released["projcurve_model_destroy"].values()) == 1
    assert sum(released["projcurve_result_destroy"].values()) == 1
    assert not released["projcurve_surface_destroy"]  # borrowed: the model's


def test_borrowed_keep_owner_alive(pc, released):
    m = pc.Model.read(data("cases-brep", "shell_2x2.step"))
    s, face, shape = m.surfaces[0], m.faces[1], m.shapes[0]
    del m
    gc.collect()
    assert not released["projcurve_model_destroy"]
    assert s.domain and face.loops and shape.edges  # the model is still there
    del s, face, shape
    gc.collect()
    assert sum(released["projcurve_model_destroy"].values()) == 1


def test_dependents(pc, released, bilinear):
    face = pc.Face.create(bilinear)
    del bilinear
    gc.collect()
    assert face.classify(0.5, 0.5) == pc.Where.IN  # the face keeps its surface
    surface = face.surface
    surface.close()  # closes the face first, then the surface
    assert face.closed
    assert list(released["projcurve_face_destroy"].values()) == [1]
    assert list(released["projcurve_surface_destroy"].values()) == [1]


def test_cycles(pc, released):
    m = pc.Model.read(data("cases-brep", "shell_2x2.step"))
    s = m.surfaces[0]
    s.cycle, m.cycle = m, s  # a reference cycle through both wrappers
    face = pc.Face.create(s)
    face.cycle = face
    del m, s, face
    gc.collect()
    assert sum(released["projcurve_model_destroy"].values()) == 1
    assert sum(released["projcurve_face_destroy"].values()) == 1


def test_results_outlive_inputs(pc, bilinear, segment):
    r = pc.project_directional(bilinear, segment, (0, 0, -1))
    bilinear.close()
    segment.close()
    (b,) = r.branches
    assert b.tuv() and b.pieces and b.compact_curve().domain == b.t_range
    with pytest.raises(pc.NullArgumentError):
        b.points()  # 3D points evaluate the (closed) surface
