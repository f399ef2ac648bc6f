# SPDX-License-Identifier: BSD-3-Clause
"""Arrays in and out: lists, tuples, generators and numpy arrays give the
same handles, and the data read back is the data given, bit for bit."""
import pytest

KU = [0, 0, 0, 0.5, 1, 1, 1]
KV = [0, 0, 1, 1]
NET = [[i / 3.0, j * 0.7, 0.1 * i * j + 0.01 * i * i] for j in range(2) for i in range(4)]
W = [1.0, 0.8, 1.3, 1.0, 0.9, 1.0, 1.1, 1.0]
CURVE = [[0.0, 0.1, 1.0], [0.3, 0.9, 1.2], [0.7, 0.2, 0.8], [1.0, 0.6, 1.0]]
CK = [0, 0, 0, 0.4, 1, 1, 1]


def test_lists_round_trip(pc):
    s = pc.Surface.from_nurbs((2, 1), (4, 2), NET, (KU, KV))
    assert s.control_points() == [tuple(p) for p in NET]
    assert s.weights() == [1.0] * 8 and s.knots() == (KU, KV) and not s.rational
    # rational nets are stored homogeneous (w P): P comes back to rounding
    r = pc.Surface.from_nurbs((2, 1), (4, 2), NET, (KU, KV), weights=W)
    assert r.weights() == W and r.rational
    assert all(abs(a - b) <= 4e-16 * max(1.0, abs(b))
               for p, q in zip(r.control_points(), NET) for a, b in zip(p, q))
    c = pc.Curve.from_nurbs(2, (tuple(p) for p in CURVE), tuple(CK), weights=[1, 2, 1, 1])
    assert c.control_points() == [tuple(p) for p in CURVE] and c.knots() == CK
    assert c.weights() == [1, 2, 1, 1] and c.rational


def test_numpy_round_trip(pc):
    np = pytest.importorskip("numpy")
    net = np.array(NET).reshape(2, 4, 3)  # (n_v, n_u, 3): u fastest
    s = pc.Surface.from_nurbs((2, 1), (4, 2), net, (np.array(KU), KV))
    ctrl = s.control_points(numpy=True)
    assert isinstance(ctrl, np.ndarray) and ctrl.shape == (8, 3)
    assert np.array_equal(ctrl, net.reshape(8, 3))
    ku, kv = s.knots(numpy=True)
    assert np.array_equal(ku, KU) and np.array_equal(kv, KV)
    assert np.array_equal(s.weights(numpy=True), [1.0] * 8)
    r = pc.Surface.from_nurbs((2, 1), (4, 2), net, (KU, KV), weights=np.array(W))
    assert np.array_equal(r.weights(numpy=True), W)
    # non-contiguous and integer arrays are converted
    c = pc.Curve.from_nurbs(2, np.array(CURVE)[:, :], np.array(CK)[::1])
    assert np.array_equal(c.control_points(numpy=True), CURVE)
    ci = pc.Curve.from_nurbs(1, np.array([[0, 0, 0], [2, 1, 0]], dtype=np.int32), [0, 0, 1, 1])
    assert ci.control_points() == [(0, 0, 0), (2, 1, 0)]
    strided = np.array(CURVE)[::-1][::-1]
    assert pc.Curve.from_nurbs(2, strided, CK).control_points() == [tuple(p) for p in CURVE]
    assert np.array_equal(c.points(np.array([0.0, 0.5]), numpy=True),
                          c.points([0.0, 0.5], numpy=True))
    with pytest.raises(pc.InvalidArgumentError):
        pc.Curve.from_nurbs(1, np.array([["a"] * 3] * 2), [0, 0, 1, 1])
    with pytest.raises(pc.BadCountError):
        pc.Curve.from_nurbs(1, np.zeros((2, 2)), [0, 0, 1, 1])


def test_numpy_and_lists_give_the_same_projection(pc, bilinear, segment):
    np = pytest.importorskip("numpy")
    res = pc.project_directional(bilinear, segment, np.array([0.0, 0.0, -1.0]))
    ref = pc.project_directional(bilinear, segment, [0, 0, -1])
    (b,), (r,) = res.branches, ref.branches
    tuv = b.tuv(numpy=True)
    assert tuv.shape == (b.n_points, 3) and tuv.dtype == np.float64
    assert [tuple(row) for row in tuv] == r.tuv()
    assert np.array_equal(b.uv(numpy=True), r.uv())
    assert np.array_equal(b.points(numpy=True), r.points())
    assert np.array_equal(b.t(numpy=True), r.t())
    s2 = pc.Surface.from_nurbs((1, 1), (2, 2), bilinear.control_points(numpy=True),
                               bilinear.knots(numpy=True))
    assert s2.control_points() == bilinear.control_points()
    assert s2.points(np.array([[0.5, 0.25]]), numpy=True).tolist() == [[0.5, 0.25, 0.125]]


def test_numpy_output_without_numpy(pc, segment, monkeypatch):
    monkeypatch.setattr(pc._arrays, "_np", None)
    with pytest.raises(ImportError):
        segment.control_points(numpy=True)
    assert segment.control_points() == [(0.1, 0.2, 2.0), (0.9, 0.7, 2.0)]


def test_empty(pc, bilinear, segment):
    assert bilinear.points([]) == [] and segment.points([]) == []
    with pytest.raises(pc.BadCountError):
        pc.Curve.from_nurbs(1, [], [0, 0, 1, 1])
