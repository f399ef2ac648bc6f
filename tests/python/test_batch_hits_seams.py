# SPDX-License-Identifier: BSD-3-Clause
"""The many-curve calls (the same results as one call per curve, bit for
bit, whatever the thread count; per-curve failures), the hits options
(nearest, max_distance) and the seams of a branch across a closed
surface, each checked against geometry the test knows: a cylinder seen
from its axis, a sphere seen from outside."""
import math

import pytest

from conftest import data

from test_against_c import package_lines


def curves(pc):
    out = []
    for k in range(5):
        a = 0.1 + 0.05 * k
        out.append(pc.Curve.from_nurbs(1, [[a, 0.2, 2], [0.9, 0.9 - a, 2]], [0, 0, 1, 1]))
    return out


@pytest.mark.parametrize("threads", [1, 3])
def test_curves_directional_match_single_calls(pc, bilinear, threads):
    cs = curves(pc)
    got = pc.project_curves_directional(bilinear, cs, (0, 0.2, -1), threads=threads,
                                        tol_distance=1e-6)
    assert len(got) == len(cs)
    for c, r in zip(cs, got):
        one = pc.project_directional(bilinear, c, (0, 0.2, -1), tol_distance=1e-6)
        assert r.status == pc.Status.OK and r.curve is c
        assert package_lines(pc, r) == package_lines(pc, one)  # floats compared exactly


@pytest.mark.parametrize("threads", [1, 2])
def test_curves_orthogonal_match_single_calls(pc, bilinear, threads):
    cs = curves(pc)
    got = pc.project_curves_orthogonal(bilinear, cs, threads=threads)
    for c, r in zip(cs, got):
        assert package_lines(pc, r) == package_lines(pc, pc.project_orthogonal(bilinear, c))
    assert pc.project_curves_orthogonal(bilinear, []) == []


def test_curves_failures(pc, bilinear):
    cs = curves(pc)
    with pytest.raises(pc.ZeroDirectionError) as info:
        pc.project_curves_directional(bilinear, cs, (0, 0, 0))
    assert info.value.results == [] and info.value.statuses == []  # nothing ran
    with pytest.raises(pc.NotFiniteError):
        pc.project_curves_directional(bilinear, cs, (0, math.nan, -1))
    with pytest.raises(pc.OutOfRangeError) as info:
        pc.project_curves_directional(bilinear, cs, (0, 0, -1), threads=0)
    assert info.value.message
    # every curve cut by the work limit: the first one's error, all results kept
    with pytest.raises(pc.LimitReachedError) as info:
        pc.project_curves_directional(bilinear, cs, (0, 0, -1), max_work=1)
    e = info.value
    assert e.message.startswith("curve 0: ") and len(e.results) == len(cs)
    assert all(s == pc.Status.ERR_LIMIT_REACHED for s in e.statuses)
    assert all(r is not None and r.status == pc.Status.ERR_LIMIT_REACHED for r in e.results)
    partial = pc.project_curves_directional(bilinear, cs, (0, 0, -1), max_work=1,
                                            allow_partial=True)
    assert [r.status for r in partial] == e.statuses
    # a curve that is a point fails alone, the others are projected
    dot = pc.Curve.from_nurbs(1, [[0.5, 0.5, 2], [0.5, 0.5, 2]], [0, 0, 1, 1])
    with pytest.raises(pc.SingularError) as info:
        pc.project_curves_directional(bilinear, [cs[0], dot, cs[1]], (0, 0, -1))
    e = info.value
    assert e.message.startswith("curve 1: ")
    assert e.statuses == [pc.Status.OK, pc.Status.ERR_SINGULAR, pc.Status.OK]
    assert e.results[1] is None and len(e.results[0].branches) == len(e.results[2].branches) == 1
    cs[2].close()
    with pytest.raises(pc.NullArgumentError):
        pc.project_curves_directional(bilinear, cs, (0, 0, -1))


def sphere_case(pc):
    m = pc.Model.read(data("cases-brep", "sphere_analytic.step"))
    c = pc.Model.read(data("cases-brep", "sphere_analytic_conical_outside.curves.igs")).curves[0]
    return m.surfaces[0], c


EYE = (0.0, 0.0, 40.0)


def test_hits_nearest_on_a_sphere(pc):
    # From (0, 0, 40) the sphere of radius 10 at the origin shows the cap
    # z > 10 * 10 / 40 = 2.5 (the tangent cone touches it there): every
    # ray through the curve enters the cap and leaves below it.
    s, c = sphere_case(pc)
    every = pc.project_conical(s, c, EYE, tol_distance=1e-3)
    front = pc.project_conical(s, c, EYE, tol_distance=1e-3, hits=pc.HITS_NEAREST)
    assert len(every.branches) == 2 and len(front.branches) == 1
    zs = [p[2] for p in front.branches[0].points()]
    assert min(zs) > 2.5
    back = [b for b in every.branches if max(p[2] for p in b.points()) < 2.5]
    assert len(back) == 1
    # the branch kept is the front one of the full result, point for point
    kept = [b for b in every.branches if b not in back][0]
    assert front.branches[0].tuv() == kept.tuv()


def test_max_distance_on_a_sphere(pc):
    s, c = sphere_case(pc)
    d = 20.0  # the curve is ~11 above the front cap, ~27 above the back
    r = pc.project_conical(s, c, EYE, tol_distance=1e-3, max_distance=d)
    assert len(r.branches) == 1
    for t, q in zip(r.branches[0].t(), r.branches[0].points()):
        p = c.point(t)
        assert math.dist(p, q) <= d
    assert pc.Options(max_distance=math.inf).max_distance == 0.0  # no limit, as documented
    with pytest.raises(pc.OutOfRangeError):
        pc.Options(max_distance=-1.0)
    with pytest.raises(pc.OutOfRangeError):
        pc.Options(hits=2)


def test_seam_of_a_cylinder(pc):
    # The eye on the axis of the closed cylinder of radius 10; the curve
    # inside crosses the seam u = 0 = 2 pi: one branch whose pcurve jumps
    # by the period there, the traced point repeated on both sides.
    m = pc.Model.read(data("cases-brep", "cylinder_analytic.step"))
    s = m.surfaces[0]
    c = pc.Model.read(data("cases-brep", "cyl_analytic_seam_conical.curves.igs")).curves[0]
    eye = (0.0, 0.0, 10.0)
    r = pc.project_conical(s, c, eye, tol_distance=1e-3)
    assert len(r.branches) == 1
    b = r.branches[0]
    seams = b.seams
    assert len(seams) == 1 and isinstance(seams[0], pc.Seam)
    period = s.domain[1] - s.domain[0]
    assert abs(abs(seams[0].du) - period) < 1e-12 and abs(seams[0].dv) < 1e-9
    tuv = b.tuv()
    # the header speaks of two vertices at the same t_k; they are the ends
    # of the two traced halves, whose t agree to ~1e-11 (1e-9 here)
    at = [k for k, row in enumerate(tuv) if abs(row[0] - seams[0].t) < 1e-9]
    assert len(at) == 2 and at[1] == at[0] + 1
    assert abs(tuv[at[1]][1] - tuv[at[0]][1] - seams[0].du) < 1e-12
    before, after = s.point(*tuv[at[0]][1:]), s.point(*tuv[at[1]][1:])
    assert math.dist(before, after) < 1e-9  # one point of S, two (u, v)
    # every traced point on the wall and on its ray from the eye
    for (t, u, v), q in zip(tuv, b.points()):
        assert abs(math.hypot(q[0], q[1]) - 10) < 1e-9
        p = c.point(t)
        ray = [a - e for a, e in zip(p, eye)]
        w = [a - e for a, e in zip(q, eye)]
        cr = [ray[1] * w[2] - ray[2] * w[1], ray[2] * w[0] - ray[0] * w[2],
              ray[0] * w[1] - ray[1] * w[0]]
        assert math.hypot(*cr) / math.hypot(*ray) < 1e-9
    assert r.branches[0].seams == seams
