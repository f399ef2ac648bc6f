# SPDX-License-Identifier: BSD-3-Clause
"""project_face and project_shape through the package, judged by geometry:
the 2 x 2 shell of shell_2x2.step gives one connected curve of four face
pieces whose ends meet across the shared edges; every point lies on its
face (not outside its loops) and on its ray; a face with a hole cuts the
branch exactly on the hole; bad input raises the status's exception."""
import math

import pytest

from conftest import data

DIR = (0.2, -0.1, -1.0)  # the case's direction (cases-brep/MANIFEST.tsv)


def shell(pc):
    m = pc.Model.read(data("cases-brep", "shell_2x2.step"))
    c = pc.Model.read(data("cases-brep", "shell_2x2_bspline_oblique.curves.igs")).curves[0]
    return m, c


def off_ray(p, q, d):
    w = [a - b for a, b in zip(q, p)]
    cr = [w[1] * d[2] - w[2] * d[1], w[2] * d[0] - w[0] * d[2], w[0] * d[1] - w[1] * d[0]]
    return math.hypot(*cr) / math.hypot(*d), sum(a * b for a, b in zip(w, d))


def test_shape_connected_curve(pc):
    m, c = shell(pc)
    shape = m.shapes[0]
    r = pc.project_shape(shape, c, DIR, tol_distance=1e-3)
    assert r.status == pc.Status.OK and r.open_end_count == 0 and r.chain_tolerance > 0
    assert len(r.curves) == 1
    cc = r.curves[0]
    assert len(cc.pieces) == 4 and not cc.closed
    assert cc.pieces[0].start == pc.BranchStart.CURVE_START
    assert cc.pieces[-1].end == pc.BranchEnd.CURVE_END
    assert sorted(p.face for p in cc.pieces) == [0, 1, 2, 3]
    faces = shape.faces
    for a, b in zip(cc.pieces, cc.pieces[1:]):
        assert a.end == pc.BranchEnd.TRIM and b.start == pc.BranchStart.TRIM
        # the crossing is located to 1e-10 of the model size (20 wide) on
        # both faces: the two ends are one point of the shared edge
        assert abs(a.t_range[1] - b.t_range[0]) < 1e-9
        assert math.dist(a.branch.points()[-1], b.branch.points()[0]) < 1e-8
    for p in cc.pieces:
        face = faces[p.face]
        for (t, u, v), q in zip(p.branch.tuv(), p.branch.points()):
            assert face.classify(u, v) != pc.Where.OUT
            dist, along = off_ray(c.point(t), q, DIR)
            assert dist < 1e-8 and along >= 0  # corrector tolerance on a model 20 wide
    assert [f.status for f in r.faces] == [pc.Status.OK] * 4


def test_shape_result_written_whole(pc, tmp_path):
    # one composite curve per connected curve: the IGES 102 is read back as
    # its members joined (one curve), the STEP COMPOSITE_CURVE's B-splines
    # as the four pieces, each starting where the one before ended
    m, c = shell(pc)
    r = pc.project_shape(m.shapes[0], c, DIR, tol_distance=1e-3)
    w = pc.IgesWriter()
    w.add_shape_result(r)
    w.write(tmp_path / "shape.igs")
    sw = pc.StepWriter()
    sw.add_shape_result(r)
    sw.write(tmp_path / "shape.step")
    assert len(pc.Model.read(tmp_path / "shape.igs").curves) == 1
    pieces = pc.Model.read(tmp_path / "shape.step").curves
    assert len(pieces) == 4
    for a, b in zip(pieces, pieces[1:]):
        assert math.dist(a.point(a.domain[1]), b.point(b.domain[0])) <= r.chain_tolerance


def test_face_with_a_hole(pc, bilinear):
    # the hole [0.4, 0.6]^2 of the domain; the line y = 0.5 crosses it
    square = [(0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6), (0.4, 0.4)]
    hole = [{"degree": 1, "control_points": [a, b], "knots": [0, 0, 1, 1]}
            for a, b in zip(square, square[1:])]
    outer_pts = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
    outer = [{"degree": 1, "control_points": [a, b], "knots": [0, 0, 1, 1]}
             for a, b in zip(outer_pts, outer_pts[1:])]
    face = pc.Face.create(bilinear, [outer, hole])
    line = pc.Curve.from_nurbs(1, [[0.1, 0.5, 2], [0.9, 0.5, 2]], [0, 0, 1, 1])
    r = pc.project_face(face, line, (0, 0, -1), tol_distance=1e-6)
    ranges = sorted(p.t_range for cc in r.curves for p in cc.pieces)
    # x = 0.1 + 0.8 t meets the hole at x = 0.4 and 0.6: t = 3/8 and 5/8
    assert len(ranges) == 2
    assert abs(ranges[0][1] - 0.375) < 1e-10 and abs(ranges[1][0] - 0.625) < 1e-10
    ends = [p.end for cc in r.curves for p in cc.pieces]
    assert pc.BranchEnd.TRIM in ends
    orth = pc.project_face(face, line)
    assert len(orth.faces) == 1


def test_bad_input(pc):
    m, c = shell(pc)
    with pytest.raises(pc.InvalidArgumentError):
        pc.project_shape(m.shapes[0], c, DIR, eye=(0, 0, 50))
    # the curve passes through this eye: no ray, the call refuses it
    t0, t1 = c.domain
    with pytest.raises(pc.SingularError):
        pc.project_face(m.faces[0], c, eye=tuple(c.point(0.5 * (t0 + t1))))
    with pytest.raises(pc.ZeroDirectionError):
        pc.project_shape(m.shapes[0], c, (0, 0, 0))
    with pytest.raises(pc.NotFiniteError):
        pc.project_face(m.faces[0], c, (0, math.nan, -1))
    with pytest.raises(pc.BadCountError):
        pc.project_face(m.faces[0], c, (0, -1))
    r = pc.project_shape(m.shapes[0], c, DIR)
    r.close()
    with pytest.raises(pc.NullArgumentError):
        r.curves
    c.close()
    with pytest.raises(pc.NullArgumentError):
        pc.project_shape(m.shapes[0], c, DIR)
