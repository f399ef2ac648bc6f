# SPDX-License-Identifier: BSD-3-Clause
"""Every public call of the package, on shapes whose answers are known:
the bilinear patch z = u v (x = u, y = v), planes and a sphere.

Tolerances: traced points are corrected by Newton to 1e-12 of the model
size (PROJCURVE_OPT_NEWTON_TOL), so on these unit-sized shapes they lie
within 1e-11 of the exact projection; composed pieces on a bilinear patch
with straight pcurves are exact (degree p + q = 2 Bezier of S o pcurve),
to rounding (1e-13); compact curves are within eps_D."""
import math

import pytest

from conftest import data


def lerp(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


A, B = (0.1, 0.2, 2.0), (0.9, 0.7, 2.0)


def exact(t):
    x, y, _ = lerp(A, B, t)
    return (x, y, x * y)


def close(p, q, tol):
    return all(abs(a - b) <= tol for a, b in zip(p, q))


def test_module(pc):
    assert pc.__version__ == pc.library_version()
    assert pc.library_path().endswith(pc._lib.SONAME) or "libprojcurve" in pc.library_path()
    assert pc.status_string(pc.Status.OK) == "ok"
    assert pc.status_string(pc.Status.ERR_VERSION) == "version mismatch"
    assert pc.MAX_DEGREE == 30 and pc.METHOD_RK4 == 1 and pc.MAX_PIECE_POINTS == 61
    assert set(pc.option_table()) == set(pc.Options.names())
    assert pc.Where.IN == 1 and pc.ShapeKind.SOLID == 0 and pc.Stat.POINTS == 0
    assert pc.BranchStart.CURVE_START == 0 and pc.BranchEnd.CURVE_END == 0


def test_surface_queries(pc, bilinear):
    s = bilinear
    assert s.domain == (0.0, 1.0, 0.0, 1.0)
    assert s.info == pc.SurfaceInfo((1, 1), (2, 2), (1, 1), False)
    assert s.degree == (1, 1) and s.shape == (2, 2) and not s.rational and s.kind is None
    assert s.control_points() == [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 1)]
    assert s.weights() == [1.0] * 4
    assert s.knots() == ([0, 0, 1, 1], [0, 0, 1, 1])
    S, Su, Sv = s.eval(0.3, 0.6, 1)
    assert close(S, (0.3, 0.6, 0.18), 1e-15) and close(Su, (1, 0, 0.6), 1e-15)
    assert close(Sv, (0, 1, 0.3), 1e-15)
    assert len(s.eval(0.3, 0.6, 2)) == 6
    assert close(s.point(0.5, 0.5), (0.5, 0.5, 0.25), 1e-15)
    assert all(close(p, (u, v, u * v), 1e-15)
               for p, (u, v) in zip(s.points([(0, 0), (0.25, 0.5)]), [(0, 0), (0.25, 0.5)]))
    assert s.bounds == (0, 0, 0, 1, 1, 1)
    cp = s.closest_point((0.5, 0.5, 0.25))
    assert close(cp.parameter, (0.5, 0.5), 1e-9) and cp.distance <= 1e-9
    feet = s.foot_points((0.5, 0.5, 1.0))
    assert feet and all(len(f) == 2 for f in feet)
    hits = s.intersect_line((0.3, 0.4, 5), (0, 0, -1))
    assert len(hits) == 1 and close((hits[0].u, hits[0].v), (0.3, 0.4), 1e-12)
    assert abs(hits[0].lam - (5 - 0.12)) <= 1e-12
    assert s.intersect_line((0.3, 0.4, 5), (0, 0, 1), ray_only=True) == []


def test_curve_queries(pc, segment):
    c = segment
    assert c.domain == (0.0, 1.0)
    assert c.info == pc.CurveInfo(1, 2, 4, False)
    assert c.degree == 1 and not c.rational
    assert c.control_points() == [A, B] and c.knots() == [0, 0, 1, 1] and c.weights() == [1, 1]
    P, dP = c.eval(0.25, 1)
    assert close(P, lerp(A, B, 0.25), 1e-15) and close(dP, (0.8, 0.5, 0), 1e-15)
    assert close(c.point(0.5), lerp(A, B, 0.5), 1e-15)
    assert all(close(p, lerp(A, B, t), 1e-15) for p, t in zip(c.points([0, 0.5, 1]), [0, 0.5, 1]))
    cp = c.closest_point((0.5, 0.45, 3))
    assert abs(cp.parameter - 0.5) <= 1e-9 and abs(cp.distance - 1.0) <= 1e-9
    assert close(cp.point, lerp(A, B, 0.5), 1e-9)


def test_directional_result(pc, bilinear, segment):
    res = pc.project_directional(bilinear, segment, (0, 0, -1), tol_distance=1e-6)
    assert res.status == pc.Status.OK and res.message == ""
    assert res.point_dim == 3 and res.failure_count == 0
    assert res.surface is bilinear and res.curve is segment
    (b,) = res.branches
    assert b.t_range == (0.0, 1.0)
    assert b.start == pc.BranchStart.CURVE_START and b.end == pc.BranchEnd.CURVE_END
    tuv = b.tuv()
    assert len(tuv) == b.n_points >= 2 and b.t() == [p[0] for p in tuv]
    for (t, u, v), uv, p in zip(tuv, b.uv(), b.points()):
        assert (u, v) == uv
        assert close(p, exact(t), 1e-11)
    pieces = b.pieces
    assert len(pieces) == b.n_pieces >= 1
    for piece in pieces:
        # cubic pcurves by default (3 (p + q) = 6 on a bilinear patch)
        d, n = piece.pcurve_degree, piece.degree
        assert d == 3 and n == 2 * d and piece.weights == [1.0] * (n + 1)
        uv_ctrl = piece.pcurve_control_points
        assert len(uv_ctrl) == d + 1
        assert close(piece.uv_range, uv_ctrl[0] + uv_ctrl[-1], 1e-15)
        for s in (0.0, 0.3, 1.0):  # the Bezier piece is S o pcurve
            uv = [sum(math.comb(d, i) * s ** i * (1 - s) ** (d - i) * uv_ctrl[i][k]
                      for i in range(d + 1)) for k in range(2)]
            bez = [sum(math.comb(n, i) * s ** i * (1 - s) ** (n - i) * piece.control_points[i][k]
                       for i in range(n + 1)) for k in range(3)]
            assert close(bez, bilinear.point(*uv), 1e-13)
    joined = b.curve()
    assert joined.domain == b.t_range
    for curve in (joined, b.compact_curve()):
        for t in (0.0, 0.37, 1.0):
            assert close(curve.point(t), exact(t), 1e-6)
    q = b.compact_pcurve()
    for t in (0.0, 0.5, 1.0):
        u, v, w = q.point(t)
        assert w == 0.0 and close(bilinear.point(u, v), exact(t), 1e-6)
    info = b.compact_info()
    assert info.pcurve_fitted in (True, False) and 0 <= info.curve_error <= 1e-6
    assert res.stat("pieces") == len(pieces) and res.stat(pc.Stat.POINTS) >= len(tuv)
    assert res.stats["tol_distance"] == 1e-6 and set(res.stats) == {s.name.lower() for s in pc.Stat}
    assert "Branch(0" in repr(b)


def test_compact_exact(pc, bilinear, segment):
    """S o q on the bilinear patch: q is the segment's own (u, v) line, so
    the composition is (x, y, x y) of the segment exactly: degree
    1 (1 + 1) = 2, to rounding (1e-13)."""
    res = pc.project_directional(bilinear, segment, (0, 0, -1), tol_distance=1e-6)
    (b,) = res.branches
    e = b.compact_exact()
    assert e.domain == b.t_range and e.degree == 2
    for t in (0.0, 0.21, 0.5, 0.77, 1.0):
        assert close(e.point(t), exact(t), 1e-13)
    assert close(b.compact_exact(bilinear).point(0.4), exact(0.4), 1e-13)
    lifted = pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                                   control_points=[[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]],
                                   knots=([0, 0, 1, 1], [0, 0, 1, 1]))
    with pytest.raises(pc.InvalidArgumentError):
        b.compact_exact(lifted)  # not the surface projected onto


def test_orthogonal_onto_plane(pc):
    plane = pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                                  control_points=[[0, 0, 0], [2, 0, 0], [0, 2, 0], [2, 2, 0]],
                                  knots=([0, 0, 1, 1], [0, 0, 1, 1]))
    line = pc.Curve.from_nurbs(1, [[0.2, 0.4, 1], [1.6, 1.2, 3]], [0, 0, 1, 1])
    opts = pc.Options(tol_distance=1e-6)
    res = pc.project_orthogonal(plane, line, opts)
    (b,) = res.branches
    for (t, u, v), p in zip(b.tuv(), b.points()):
        x, y, _ = line.point(t)
        assert close(p, (x, y, 0.0), 1e-11) and close((2 * u, 2 * v), (x, y), 1e-11)


def test_orthogonal_implicit_sphere(pc):
    def sphere(x):
        return (x[0] ** 2 + x[1] ** 2 + x[2] ** 2 - 1.0, [2 * x[0], 2 * x[1], 2 * x[2]],
                [[2, 0, 0], [0, 2, 0], [0, 0, 2]])
    arc = pc.Curve.from_nurbs(1, [[2, 0, 0.5], [0, 2, 0.5]], [0, 0, 1, 1])
    res = pc.project_orthogonal_implicit(sphere, 2.0, arc, tol_distance=1e-6)
    assert res.point_dim == 4 and res.surface is None
    (b,) = res.branches
    for (t, *q), p in zip(b.tuv(), b.points()):
        P = arc.point(t)
        r = math.sqrt(sum(a * a for a in P))
        assert tuple(q) == p and close(p, [a / r for a in P], 1e-9)
    with pytest.raises(pc.InvalidArgumentError):
        b.uv()
    assert all(piece.pcurve_degree is None for piece in b.pieces)


def test_callback_curve(pc, bilinear, segment):
    def line(t):
        return list(lerp(A, B, t)) + [0.8, 0.5, 0.0] + [0.0, 0.0, 0.0]
    c = pc.Curve.from_function(line, 0.0, 1.0)
    assert c.domain == (0.0, 1.0)
    assert close(c.point(0.5), lerp(A, B, 0.5), 1e-15)
    res = pc.project_directional(bilinear, c, (0, 0, -1), tol_distance=1e-6)
    (b,) = res.branches
    assert b.t_range == (0.0, 1.0)
    assert all(close(p, exact(t), 1e-11) for (t, _, _), p in zip(b.tuv(), b.points()))
    with pytest.raises(pc.WrongKindError):
        c.info
    bad = pc.Curve.from_function(lambda t: 1 / 0, 0.0, 1.0)
    with pytest.raises(pc.CallbackError):
        bad.point(0.5)


def test_options(pc):
    o = pc.Options(tol_distance=1e-5, method=pc.METHOD_RK4)
    assert o.tol_distance == 1e-5 and o["method"] == 1 and o.get("method") == 1
    o.tol_angle_deg = 0.5
    o["max_points"] = 2 ** 40  # 64-bit integers pass intact
    o.set("compose", 0)
    assert o.tol_angle_deg == 0.5 and o.max_points == 2 ** 40 and o.compose == 0
    info = pc.Options.info("max_points")
    assert info.type == pc.OptionType.INTEGER
    assert (info.min, info.max, info.default) == (16, 2 ** 40, 100000)
    assert pc.Options.info("tol_angle_deg").type == pc.OptionType.DOUBLE
    assert dict(o.items())["tol_angle_deg"] == 0.5
    # Every option of the header's enum is known to the library, with its default.
    fresh = pc.Options()
    assert [n.upper() for n in pc.Options.names()] == [opt.name for opt in pc.Option]
    for name in pc.Options.names():
        assert fresh.get(name) == pc.Options.info(name).default
    o.close()
    assert o.closed


def test_progress_and_limits(pc, bilinear, segment):
    seen = []
    o = pc.Options(tol_distance=1e-6)
    o.progress = lambda f: seen.append(f)
    assert o.progress is not None
    pc.project_directional(bilinear, segment, (0, 0, -1), o)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen)
    o.progress = lambda f: True
    with pytest.raises(pc.CancelledError) as info:
        pc.project_directional(bilinear, segment, (0, 0, -1), o)
    assert info.value.result is not None and "asked to stop" in info.value.message
    res = pc.project_directional(bilinear, segment, (0, 0, -1), o, allow_partial=True)
    assert res.status == pc.Status.ERR_CANCELLED

    def boom(f):
        raise ZeroDivisionError("from the progress function")
    o.progress = boom
    with pytest.raises(ZeroDivisionError):
        pc.project_directional(bilinear, segment, (0, 0, -1), o)
    o.progress = None
    assert o.progress is None
    with pytest.raises(pc.LimitReachedError) as info:
        pc.project_directional(bilinear, segment, (0, 0, -1), o, max_work=1)
    assert info.value.result.status == pc.Status.ERR_LIMIT_REACHED
    assert info.value.result.message == info.value.message != ""


def test_model_iges(pc):
    with pc.Model.read(data("cases", "bumpy_bicubic_8x8_down.igs")) as m:
        (s,) = m.surfaces
        assert s.kind == "bspline" and s.degree == (3, 3) and s.shape == (8, 8)
        assert len(m.curves) == 1 and isinstance(m.skipped, list)
        assert m.length_unit is None or m.length_unit > 0
        assert m.precision is None or m.precision > 0
        res = pc.project_directional(s, m.curves[0], (0, 0, -1), tol_distance=1e-3)
        assert len(res.branches) == 1


def test_model_step_faces_shapes(pc):
    path = data("cases-brep", "shell_2x2.step")
    m = pc.Model.read(path)
    with open(path, "rb") as f:
        m2 = pc.Model.from_bytes(f.read())
    assert len(m2.faces) == len(m.faces) == 4 and len(m2.surfaces) == len(m.surfaces)
    assert m.length_unit == 0.001 and m.unbuilt_faces == []
    (shape,) = m.shapes
    assert shape.kind in (pc.ShapeKind.OPEN_SHELL, pc.ShapeKind.CLOSED_SHELL)
    assert shape.sew_tolerance >= 0
    assert len(shape.faces) == 4 and sorted(shape.face_model_indices) == [0, 1, 2, 3]
    edges = shape.edges
    assert edges and all(1 <= len(e.uses) <= 2 for e in edges)
    assert sum(len(e.uses) == 2 for e in edges) == 4  # the inner edges of a 2 x 2 shell
    for e in edges:
        for use in e.uses:
            piece = m.faces[shape.face_model_indices[use.face]].loops[use.loop][use.piece]
            assert piece.edge == e.id
    face = m.faces[0]
    (uv_box, box) = face.bounds
    u, v = (uv_box[0] + uv_box[1]) / 2, (uv_box[2] + uv_box[3]) / 2
    assert face.classify(u, v) == pc.Where.IN
    assert face.classify(uv_box[1] + 1, v) == pc.Where.OUT
    assert face.tolerance[0] > 0
    fi = face.info
    assert fi.same_sense in (1, -1) and fi.kind == "bspline" and fi.periodic == (False, False)
    assert face.surface.domain is not None and len(face.loops[0]) >= 1


def test_face_create(pc, bilinear):
    corners = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]
    outer = [{"degree": 1, "control_points": [corners[i], corners[(i + 1) % 4]],
              "knots": [0, 0, 1, 1]} for i in range(4)]
    hole = [{"degree": 1, "control_points": [(0.4, 0.4), (0.4, 0.6), (0.6, 0.6), (0.6, 0.4),
                                             (0.4, 0.4)],
             "knots": [0, 0, 1, 2, 3, 4, 4], "weights": [1, 1, 1, 1, 1]}]
    face = pc.Face.create(bilinear, [outer, hole])
    assert face.surface is bilinear
    assert face.classify(0.25, 0.5) == pc.Where.IN
    assert face.classify(0.5, 0.5) == pc.Where.OUT
    assert face.classify(0.05, 0.5) == pc.Where.OUT
    assert face.classify(0.1, 0.5) == pc.Where.ON
    loops = face.loops
    assert [len(loop) for loop in loops] == [4, 1]
    assert loops[0][0].control_points == [corners[0], corners[1]] and loops[0][0].weights is None
    assert loops[1][0].weights == [1.0] * 5 and loops[1][0].knots == [0, 0, 1, 2, 3, 4, 4]
    assert loops[0][0].edge == -1
    assert close(face.bounds[0], (0.1, 0.9, 0.1, 0.9), 1e-15)
    assert face.tolerance[1] == 0.0
    whole = pc.Face.create(bilinear)
    assert whole.classify(0.5, 0.5) == pc.Where.IN and len(whole.loops) == 1


def test_iges_writer(pc, bilinear, segment, tmp_path):
    res = pc.project_directional(bilinear, segment, (0, 0, -1), tol_distance=1e-6)
    path = tmp_path / "out.igs"
    with pc.IgesWriter(length_unit=0.001) as w:
        w.add_surface(bilinear)
        w.add_curve(segment)
        w.add_result(bilinear, res)
        w.add_result(bilinear, res, pieces=True)
        w.set_length_unit(0.0254)
        w.write(path)
    back = pc.Model.read(path)
    assert back.length_unit == 0.0254
    assert len(back.surfaces) >= 1
    assert close(back.surfaces[0].control_points()[3], (1, 1, 1), 1e-12)
    assert any(c.info.n_control_points == 2 and close(c.point(1.0), B, 1e-12)
               for c in back.curves)


def test_options_and_keywords_merge(pc, bilinear, segment):
    seen = []
    o = pc.Options(tol_angle_deg=0.5, compose=0)
    o.progress = seen.append
    res = pc.project_directional(bilinear, segment, (0, 0, -1), o, tol_distance=1e-6)
    assert res.stat("tol_distance") == 1e-6  # the keyword
    assert res.branches[0].n_pieces == 0  # compose=0 of the options
    assert seen and seen[-1] == 1.0  # their progress function
    assert o.tol_distance == 0.0  # the caller's options are not changed


def test_threads_share_handles(pc):
    """Handles are read-only: threads project with the same surface and
    curve at once (each call has its own context) and agree."""
    import concurrent.futures
    m = pc.Model.read(data("cases", "bumpy_bicubic_8x8_down.igs"))
    s, c = m.surfaces[0], m.curves[0]

    def run(_):
        return pc.project_directional(s, c, (0, 0, -1), tol_distance=1e-3).branches[0].tuv()
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        results = list(pool.map(run, range(8)))
    assert all(r == results[0] for r in results)
