# SPDX-License-Identifier: BSD-3-Clause
"""Bad input: each call raises the subclass of projcurve.Error of its
status, carrying the status and a message that says what was wrong (the
library's, from the call's context, or the package's for arrays it
refuses before calling)."""
import math

import pytest

from conftest import data

KNOTS = ([0, 0, 1, 1], [0, 0, 1, 1])
NET = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]]


def raises(pc, cls, fragment, call, *args, **kwargs):
    with pytest.raises(cls) as info:
        call(*args, **kwargs)
    e = info.value
    assert isinstance(e, pc.Error)
    assert isinstance(e.status, pc.Status) and pc.ERROR_CLASSES[e.status] is type(e)
    assert fragment in e.message, e.message
    assert e.message in str(e) and e.status.name in str(e)
    return e


def test_error_classes(pc):
    for status in pc.Status:
        if status == pc.Status.OK:
            continue
        cls = pc.ERROR_CLASSES[status.value]
        assert issubclass(cls, pc.Error) and getattr(pc, cls.__name__) is cls
        e = cls(status.value, "m", "f")
        assert e.status is status and e.message == "m" and e.function == "f"
    assert pc.ZeroDirectionError.__name__ == "ZeroDirectionError"


def test_surface_input(pc):
    S = pc.Surface.from_nurbs
    raises(pc, pc.BadCountError, "knots_u", S, (1, 1), (2, 2), NET, ([0, 0, 1], [0, 0, 1, 1]))
    raises(pc, pc.BadCountError, "control_points", S, (1, 1), (2, 3), NET, KNOTS)
    raises(pc, pc.BadCountError, "3 coordinates", S, (1, 1), (2, 2), [[0, 0]] * 4, KNOTS)
    raises(pc, pc.BadCountError, "rows of different lengths", S, (1, 1), (2, 2),
           [[0, 0, 0], [1, 0], [0, 1, 0], [1, 1, 1]], KNOTS)
    raises(pc, pc.InvalidArgumentError, "not a number", S, (1, 1), (2, 2),
           [[0, 0, "a"], [1, 0, 0], [0, 1, 0], [1, 1, 1]], KNOTS)
    raises(pc, pc.BadCountError, "weights", S, (1, 1), (2, 2), NET, KNOTS, weights=[1, 1])
    raises(pc, pc.BadKnotsError, "knot", S, (1, 1), (2, 2), NET, ([0, 1, 0, 1], [0, 0, 1, 1]))
    raises(pc, pc.NotFiniteError, "", S, (1, 1), (2, 2),
           [[0, 0, math.nan], [1, 0, 0], [0, 1, 0], [1, 1, 1]], KNOTS)
    raises(pc, pc.BadWeightError, "weight", S, (1, 1), (2, 2), NET, KNOTS, weights=[1, 0, 1, 1])
    raises(pc, pc.BadDegreeError, "degree", S, (0, 1), (2, 2), NET, ([0, 0, 1], [0, 0, 1, 1]))
    raises(pc, pc.BadCountError, "positive", S, (1, 1), (-1, -2), NET[:2], ([0], [0, 0]))
    raises(pc, pc.OutOfRangeError, "", S((1, 1), (2, 2), NET, KNOTS).eval, 0.5, 0.5, 10 ** 9)


def test_size_limits(pc):
    net = [[i, j, 0] for j in range(3) for i in range(3)]
    k = [0, 0, 1, 2, 2]
    raises(pc, pc.OutOfRangeError, "", pc.Surface.from_nurbs, (1, 1), (3, 3), net, (k, k),
           max_control_points=8)
    assert pc.Surface.from_nurbs((1, 1), (3, 3), net, (k, k), max_control_points=9).shape == (3, 3)
    raises(pc, pc.OutOfRangeError, "", pc.Curve.from_nurbs, 1, net, list(range(11)),
           max_control_points=8)
    raises(pc, pc.OutOfRangeError, "", pc.Model.read,
           data("cases", "bumpy_bicubic_8x8_down.igs"), max_control_points=63)
    raises(pc, pc.OutOfRangeError, "max_control_points", pc.Model.from_bytes, b"",
           max_control_points=-1)
    raises(pc, pc.OutOfRangeError, "", pc.Model.from_bytes, b"x", max_control_points=1)


def test_curve_input(pc, segment):
    C = pc.Curve.from_nurbs
    raises(pc, pc.BadCountError, "knots", C, 1, [[0, 0, 0], [1, 0, 0]], [0, 1, 1])
    raises(pc, pc.BadKnotsError, "knot", C, 1, [[0, 0, 0], [1, 0, 0]], [0, 0, 0, 0])
    raises(pc, pc.OutOfDomainError, "", segment.eval, 2.0)
    raises(pc, pc.OutOfRangeError, "", segment.eval, 0.5, 7)
    raises(pc, pc.OutOfRangeError, "not an int of C", segment.eval, 0.5, 2 ** 32)
    raises(pc, pc.BadDegreeError, "degree", C, 2 ** 32 + 1, [[0, 0, 0], [1, 0, 0]], [0] * 3)
    raises(pc, pc.NotFiniteError, "", segment.eval, math.nan)
    raises(pc, pc.BadCountError, "3 coordinates", segment.closest_point, (1, 2))


def test_projection_input(pc, bilinear, segment):
    raises(pc, pc.ZeroDirectionError, "direction", pc.project_directional, bilinear, segment,
           (0, 0, 0))
    raises(pc, pc.NotFiniteError, "", pc.project_directional, bilinear, segment,
           (0, 0, math.inf))
    raises(pc, pc.BadCountError, "direction", pc.project_directional, bilinear, segment, (0, 1))
    raises(pc, pc.UnknownOptionError, "tol_distanse", pc.project_directional, bilinear, segment,
           (0, 0, -1), tol_distanse=1e-3)
    raises(pc, pc.OutOfRangeError, "", pc.project_orthogonal, bilinear, segment,
           tol_distance=1e-30)


def test_option_input(pc):
    o = pc.Options()
    raises(pc, pc.OutOfRangeError, "TOL_ANGLE_DEG", o.set, "tol_angle_deg", 91.0)
    raises(pc, pc.NotFiniteError, "not finite", o.set, "tol_angle_deg", math.nan)
    raises(pc, pc.OutOfRangeError, "outside [1, 200]", o.set, "newton_max_iter", 0)
    raises(pc, pc.InvalidArgumentError, "integer", o.set, "newton_max_iter", 1.5)
    raises(pc, pc.InvalidArgumentError, "number", o.set, "tol_angle_deg", "x")
    raises(pc, pc.UnknownOptionError, "nope", o.set, "nope", 1)
    raises(pc, pc.UnknownOptionError, "nope", pc.Options, nope=1)
    with pytest.raises(pc.UnknownOptionError):
        o.nope = 1
    with pytest.raises(AttributeError):
        o.nope
    assert o.tol_angle_deg == 1.0  # refused values leave the option as it was


def test_result_input(pc, bilinear, segment):
    res = pc.project_directional(bilinear, segment, (0, 0, -1), compose=0)
    (b,) = res.branches
    assert b.n_pieces == 0
    raises(pc, pc.InvalidArgumentError, "", b.compact_curve)
    raises(pc, pc.InvalidArgumentError, "", b.compact_pcurve)
    raises(pc, pc.InvalidArgumentError, "", b.curve)
    raises(pc, pc.UnknownOptionError, "statistic", res.stat, "nope")


def test_files(pc, tmp_path):
    raises(pc, pc.IoError, "", pc.Model.read, tmp_path / "missing.igs")
    bad = raises(pc, pc.Error, "", pc.Model.from_bytes, b"ISO-10303-21;\nnot a step file")
    assert bad.status in (pc.Status.ERR_PARSE, pc.Status.ERR_UNSUPPORTED)
    w = pc.IgesWriter()
    raises(pc, pc.OutOfRangeError, "", w.set_length_unit, 0.5)
    raises(pc, pc.IoError, "", w.write, tmp_path / "no" / "such" / "dir.igs")


def test_closed_handles(pc, bilinear, segment):
    bilinear.close()
    raises(pc, pc.NullArgumentError, "surface is closed", bilinear.eval, 0.5, 0.5)
    raises(pc, pc.NullArgumentError, "closed", pc.project_directional, bilinear, segment,
           (0, 0, -1))


def test_bad_faces(pc, bilinear):
    open_loop = [[{"degree": 1, "control_points": [(0.1, 0.1), (0.9, 0.1)],
                   "knots": [0, 0, 1, 1]}]]
    raises(pc, pc.InvalidArgumentError, "", pc.Face.create, bilinear, open_loop)
    raises(pc, pc.InvalidArgumentError, "dict", pc.Face.create, bilinear, [[{"degree": 1}]])
    raises(pc, pc.BadCountError, "knots", pc.Face.create, bilinear,
           [[{"degree": 1, "control_points": [(0.1, 0.1), (0.9, 0.1)], "knots": [0, 1]}]])
