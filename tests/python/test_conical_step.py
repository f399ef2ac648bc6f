# SPDX-License-Identifier: BSD-3-Clause
"""project_conical and StepWriter through the package: the conical points
checked against their definition (each on the ray from the eye through
P(t), beyond P(t)), its bad input raising the status's exception, and a
STEP file read back with the doubles it was given."""
import math

import pytest

from conftest import data

EYE = (0.5, 0.45, 20.0)


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def test_conical_points_on_their_rays(pc, bilinear, segment):
    res = pc.project_conical(bilinear, segment, EYE, tol_distance=1e-6)
    assert res.status == pc.Status.OK and len(res.branches) == 1
    b = res.branches[0]
    # The segment lies above the patch inside the cone from the eye over
    # [0, 1]^2: its whole projection is one branch over the whole curve.
    assert b.t_range == (0.0, 1.0)
    assert b.start == pc.BranchStart.CURVE_START and b.end == pc.BranchEnd.CURVE_END
    ts, uv = b.t(), b.uv()
    pts = b.points()
    assert len(ts) == len(pts) == b.n_points >= 2
    for t, (u, v), q in zip(ts, uv, pts):
        p = segment.point(t)
        ray = sub(p, EYE)
        # On the ray: the traced points are Newton solutions to about 1e-12 of
        # the model size 1; 1e-9 leaves room and still fails for a direction
        # projection (which would be off by ~1e-2 here).
        assert norm(cross(sub(q, EYE), ray)) / norm(ray) < 1e-9
        assert dot(sub(q, p), ray) >= 0  # beyond P(t), not behind it
        assert abs(q[2] - u * v) < 1e-12 and abs(q[0] - u) < 1e-12  # on S
    # The composed curve stays within tol_distance of the rays as well.
    curve = b.compact_curve()
    for k in range(11):
        t = k / 10
        p, q = segment.point(t), curve.point(t)
        assert norm(cross(sub(q, EYE), sub(p, EYE))) / norm(sub(p, EYE)) < 1e-6


def test_conical_is_not_directional(pc, bilinear, segment):
    # A far eye straight above approaches the direction (0, 0, -1); a near
    # one differs from it: the call really uses the eye.
    far = pc.project_conical(bilinear, segment, (0.5, 0.45, 1e6)).branches[0].uv()
    down = pc.project_directional(bilinear, segment, (0, 0, -1)).branches[0].uv()
    near = pc.project_conical(bilinear, segment, EYE).branches[0].uv()
    assert abs(far[0][0] - down[0][0]) < 1e-5
    assert abs(near[0][0] - down[0][0]) > 1e-2


def test_conical_bad_input(pc, bilinear, segment):
    def raises(cls, fragment, *args, **kw):
        with pytest.raises(cls) as info:
            pc.project_conical(*args, **kw)
        assert fragment in info.value.message, info.value.message
        assert info.value.function in ("projcurve_project_conical", "projcurve")
        return info.value

    raises(pc.NotFiniteError, "", bilinear, segment, (0, math.nan, 1))
    raises(pc.NotFiniteError, "", bilinear, segment, (0, math.inf, 1))
    raises(pc.BadCountError, "eye", bilinear, segment, (0, 0))
    raises(pc.InvalidArgumentError, "eye", bilinear, segment, "eye")
    on_curve = segment.point(0.25)
    e = raises(pc.SingularError, "", bilinear, segment, on_curve)
    assert e.result is None
    raises(pc.OutOfRangeError, "", bilinear, segment, EYE, tol_distance=1e-300)
    segment.close()
    raises(pc.NullArgumentError, "closed", bilinear, segment, EYE)


def test_conical_partial_result(pc, bilinear, segment):
    with pytest.raises(pc.LimitReachedError) as info:
        pc.project_conical(bilinear, segment, EYE, max_work=1)
    assert info.value.result is not None
    assert info.value.result.status == pc.Status.ERR_LIMIT_REACHED
    o = pc.Options()
    o.progress = lambda f: True
    r = pc.project_conical(bilinear, segment, EYE, o, allow_partial=True)
    assert r.status == pc.Status.ERR_CANCELLED and "asked to stop" in r.message


def test_step_writer_round_trip(pc, bilinear, segment, tmp_path):
    res = pc.project_conical(bilinear, segment, EYE, tol_distance=1e-6)
    compact = res.branches[0].compact_curve()
    path = tmp_path / "out.step"
    with pc.StepWriter(length_unit=0.0254) as w:
        w.add_surface(bilinear)
        w.add_curve(segment)
        w.add_result(bilinear, res)
        w.write(path)
    back = pc.Model.read(path)
    assert back.length_unit == 0.0254
    assert len(back.surfaces) == 1  # the surface added twice is written once
    assert back.surfaces[0].control_points() == bilinear.control_points()
    # 17 significant digits: the curves come back as the same doubles.
    got = [(c.control_points(), c.knots()) for c in back.curves]
    assert (segment.control_points(), segment.knots()) in got
    assert (compact.control_points(), compact.knots()) in got
    assert len(got) == 2


def test_step_writer_uncertainty_and_model(pc, tmp_path):
    m = pc.Model.read(data("cases", "bumpy_bicubic_8x8_down.igs"))
    res = pc.project_directional(m.surfaces[0], m.curves[0], (0, 0, -1), tol_distance=1e-3)
    path = tmp_path / "m.stp"
    w = pc.StepWriter(uncertainty=1e-5)
    w.add_result(m.surfaces[0], res)
    w.write(path)
    back = pc.Model.read(path)
    assert back.precision == pytest.approx(1e-5, rel=1e-15)
    assert len(back.curves) == len(res.branches)
    w.close()


def test_step_writer_bad_input(pc, bilinear, segment, tmp_path):
    def raises(cls, fragment, call, *args):
        with pytest.raises(cls) as info:
            call(*args)
        assert fragment in info.value.message, info.value.message

    w = pc.StepWriter()
    raises(pc.OutOfRangeError, "", w.set_length_unit, -1.0)
    raises(pc.NotFiniteError, "", w.set_length_unit, math.nan)
    raises(pc.OutOfRangeError, "", w.set_uncertainty, 0.0)
    raises(pc.NotFiniteError, "", w.set_uncertainty, math.inf)
    not_composed = pc.project_directional(bilinear, segment, (0, 0, -1), compose=0)
    raises(pc.InvalidArgumentError, "", w.add_result, bilinear, not_composed)
    raises(pc.IoError, "", w.write, tmp_path / "no" / "such" / "dir.step")
    w.close()
    raises(pc.NullArgumentError, "closed", w.add_curve, segment)
