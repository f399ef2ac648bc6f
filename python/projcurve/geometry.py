# SPDX-License-Identifier: BSD-3-Clause
"""Curves and surfaces: NURBS handles (and callback curves)."""
import collections
import ctypes

from . import _arrays
from ._errors import fail
from ._handle import Handle
from ._lib import CALLBACK_TYPES, call, call_fast, fn, limits

SurfaceInfo = collections.namedtuple("SurfaceInfo", "degree shape spans rational")
CurveInfo = collections.namedtuple("CurveInfo", "degree n_control_points n_knots rational")
ClosestPoint = collections.namedtuple("ClosestPoint", "parameter point distance")
Hit = collections.namedtuple("Hit", "u v lam flags")

_size = ctypes.c_size_t
_int = ctypes.c_int
_dbl = ctypes.c_double


def _new_handle(name, *args, max_control_points=None):
    out = ctypes.c_void_p()
    call(name, *args, ctypes.byref(out), limits=limits(max_control_points))
    return out.value


def _check_count(what, got, expected):
    if got != expected:
        raise fail("BAD_COUNT", "%s: %d values, %d expected" % (what, got, expected),
                   "projcurve")


class Curve(Handle):
    """A 3D curve: NURBS (from_nurbs, a model's, a result's) or a callback."""
    _kind = "curve"

    def __init__(self, ptr, owner=None, keep=None):
        """Wraps a C pointer: owned (released here) unless owner is given,
        the handle that owns it."""
        if owner is None:
            super().__init__(ptr, fn["projcurve_curve_destroy"])
        else:
            super().__init__(ptr, None, (owner,))
        self._keep = keep

    @classmethod
    def from_nurbs(cls, degree, control_points, knots, weights=None, max_control_points=None):
        """A B-spline (weights None) or NURBS curve: control_points is n
        points of 3 coordinates, knots n + degree + 1 values.
        max_control_points: the size limit of the call (None: the default,
        DEFAULT_MAX_CONTROL_POINTS; see PROJCURVE_LIMIT_CONTROL_POINTS)."""
        degree = _arrays.c_int(degree, "degree", "BAD_DEGREE")
        ctrl = _arrays.doubles(control_points, "control_points", dim=3)
        n = ctrl.n // 3
        k = _arrays.doubles(knots, "knots")
        _check_count("knots", k.n, n + degree + 1)
        w = None
        if weights is not None:
            w = _arrays.doubles(weights, "weights")
            _check_count("weights", w.n, n)
        return cls(_new_handle("projcurve_curve_create_nurbs", degree, n, ctrl.ptr,
                               w.ptr if w else None, k.ptr,
                               max_control_points=max_control_points))

    @classmethod
    def from_function(cls, function, t0, t1):
        """A curve given by function(t) -> 9 numbers: P(t), P'(t), P''(t).
        An exception in function makes the call using the curve fail with
        CallbackError."""
        def trampoline(_user, t, out):
            try:
                v = function(t)
                flat = _arrays.doubles(v, "curve function value")
                if flat.n != 9:
                    return 1
                for i in range(9):
                    out[i] = flat.ptr[i]
                return 0
            except Exception:  # reported by the library as a callback failure
                return 1
        cb = CALLBACK_TYPES["projcurve_curve_fn"](trampoline)
        ptr = _new_handle("projcurve_curve_create_callback", cb, None, float(t0), float(t1))
        return cls(ptr, keep=cb)

    @property
    def domain(self):
        t0, t1 = _dbl(), _dbl()
        call("projcurve_curve_domain", self._ptr, ctypes.byref(t0), ctypes.byref(t1))
        return (t0.value, t1.value)

    def eval(self, t, n_deriv=0):
        """[C(t), C'(t), ...] up to n_deriv (0..3), each an (x, y, z) tuple."""
        n = _arrays.c_int(n_deriv, "n_deriv")
        # sized for at most order 3: a larger order is refused, nothing written
        out = _arrays.out_array(3 * (min(max(n, 0), 3) + 1))
        call("projcurve_curve_eval", self._ptr, float(t), n, out)
        return _arrays.rows(out, n + 1, 3)

    def point(self, t):
        return self.eval(t)[0]

    def points(self, ts, numpy=False):
        """C(t) for every t of ts, as rows."""
        ts = _arrays.doubles(ts, "ts")
        out = _arrays.out_array(3 * ts.n)
        single = _arrays.out_array(3)
        for k in range(ts.n):
            call_fast("projcurve_curve_eval", self._ptr, ts.ptr[k], 0, single)
            out[3 * k:3 * k + 3] = single[:3]
        return _arrays.rows(out, ts.n, 3, numpy)

    @property
    def info(self):
        d, n, nk, r = _int(), _size(), _size(), _int()
        call("projcurve_curve_nurbs_info", self._ptr, ctypes.byref(d), ctypes.byref(n),
             ctypes.byref(nk), ctypes.byref(r))
        return CurveInfo(d.value, n.value, nk.value, bool(r.value))

    @property
    def degree(self):
        return self.info.degree

    @property
    def rational(self):
        return self.info.rational

    def _data(self):
        info = self.info
        ctrl = _arrays.out_array(3 * info.n_control_points)
        w = _arrays.out_array(info.n_control_points)
        k = _arrays.out_array(info.n_knots)
        call("projcurve_curve_nurbs_data", self._ptr, ctrl, w, k)
        return info, ctrl, w, k

    def control_points(self, numpy=False):
        info, ctrl, _, _ = self._data()
        return _arrays.rows(ctrl, info.n_control_points, 3, numpy)

    def weights(self, numpy=False):
        info, _, w, _ = self._data()
        return _arrays.values(w, info.n_control_points, numpy)

    def knots(self, numpy=False):
        info, _, _, k = self._data()
        return _arrays.values(k, info.n_knots, numpy)

    def closest_point(self, p):
        """ClosestPoint(parameter t, point, distance) of the curve to p."""
        p = _arrays.point(p, "p")
        t, q, d = _dbl(), _arrays.out_array(3), _dbl()
        call("projcurve_curve_closest_point", self._ptr, p.ptr, ctypes.byref(t), q,
             ctypes.byref(d))
        return ClosestPoint(t.value, tuple(q[:3]), d.value)


class Surface(Handle):
    """A B-spline or NURBS surface (from_nurbs, or a model's)."""
    _kind = "surface"

    def __init__(self, ptr, owner=None, kind=None):
        if owner is None:
            super().__init__(ptr, fn["projcurve_surface_destroy"])
        else:
            super().__init__(ptr, None, (owner,))
        self.kind = kind  # the file's surface kind for a model's surface, else None

    @classmethod
    def from_nurbs(cls, degree, shape, control_points, knots, weights=None,
                   max_control_points=None):
        """degree (p, q), shape (n_u, n_v), n_u * n_v control points with
        the u index running fastest (a flat list of points, or an array of
        shape (n_v, n_u, 3)), knots (knots_u, knots_v) of n_u + p + 1 and
        n_v + q + 1 values, weights None or n_u * n_v values;
        max_control_points as for Curve.from_nurbs."""
        p, q = (_arrays.c_int(x, "degree", "BAD_DEGREE") for x in degree)
        n_u, n_v = (int(x) for x in shape)
        if n_u < 1 or n_v < 1:
            raise fail("BAD_COUNT", "shape %r: both sizes must be positive" % ((n_u, n_v),),
                       "projcurve")
        ctrl = _arrays.doubles(control_points, "control_points", dim=3)
        _check_count("control_points (coordinates)", ctrl.n, 3 * n_u * n_v)
        if len(knots) != 2:
            raise fail("BAD_COUNT", "knots: (knots_u, knots_v) expected", "projcurve")
        ku = _arrays.doubles(knots[0], "knots_u")
        kv = _arrays.doubles(knots[1], "knots_v")
        _check_count("knots_u", ku.n, n_u + p + 1)
        _check_count("knots_v", kv.n, n_v + q + 1)
        w = None
        if weights is not None:
            w = _arrays.doubles(weights, "weights")
            _check_count("weights", w.n, n_u * n_v)
        return cls(_new_handle("projcurve_surface_create_nurbs", p, q, n_u, n_v, ctrl.ptr,
                               w.ptr if w else None, ku.ptr, kv.ptr,
                               max_control_points=max_control_points))

    @property
    def domain(self):
        """(u0, u1, v0, v1)."""
        out = _arrays.out_array(4)
        call("projcurve_surface_domain", self._ptr, out)
        return tuple(out[:4])

    @property
    def info(self):
        du, dv, nu, nv, su, sv, r = _int(), _int(), _size(), _size(), _size(), _size(), _int()
        call("projcurve_surface_info", self._ptr, *(ctypes.byref(x) for x in
                                                    (du, dv, nu, nv, su, sv, r)))
        return SurfaceInfo((du.value, dv.value), (nu.value, nv.value), (su.value, sv.value),
                           bool(r.value))

    @property
    def degree(self):
        return self.info.degree

    @property
    def shape(self):
        return self.info.shape

    @property
    def rational(self):
        return self.info.rational

    def _data(self):
        info = self.info
        (p, q), (nu, nv) = info.degree, info.shape
        ctrl, w = _arrays.out_array(3 * nu * nv), _arrays.out_array(nu * nv)
        ku, kv = _arrays.out_array(nu + p + 1), _arrays.out_array(nv + q + 1)
        call("projcurve_surface_nurbs_data", self._ptr, ctrl, w, ku, kv)
        return info, ctrl, w, ku, kv

    def control_points(self, numpy=False):
        """n_u * n_v points, u fastest (numpy: shape (n_v * n_u, 3))."""
        info, ctrl, _, _, _ = self._data()
        return _arrays.rows(ctrl, info.shape[0] * info.shape[1], 3, numpy)

    def weights(self, numpy=False):
        info, _, w, _, _ = self._data()
        return _arrays.values(w, info.shape[0] * info.shape[1], numpy)

    def knots(self, numpy=False):
        """(knots_u, knots_v)."""
        info, _, _, ku, kv = self._data()
        (p, q), (nu, nv) = info.degree, info.shape
        return (_arrays.values(ku, nu + p + 1, numpy), _arrays.values(kv, nv + q + 1, numpy))

    def eval(self, u, v, n_deriv=0):
        """[S, (Su, Sv), (Suu, Suv, Svv)] flattened up to n_deriv (0..2)."""
        n = _arrays.c_int(n_deriv, "n_deriv")
        m = min(max(n, 0), 2)  # a larger order is refused, nothing written
        count = (m + 1) * (m + 2) // 2
        out = _arrays.out_array(3 * count)
        call("projcurve_surface_eval", self._ptr, float(u), float(v), n, out)
        return _arrays.rows(out, count, 3)

    def point(self, u, v):
        return self.eval(u, v)[0]

    def points(self, uv, numpy=False):
        """S(u, v) for every (u, v) row of uv."""
        uv = _arrays.doubles(uv, "uv", dim=2)
        n = uv.n // 2
        out, single = _arrays.out_array(3 * n), _arrays.out_array(3)
        for k in range(n):
            call_fast("projcurve_surface_eval", self._ptr, uv.ptr[2 * k], uv.ptr[2 * k + 1], 0,
                      single)
            out[3 * k:3 * k + 3] = single[:3]
        return _arrays.rows(out, n, 3, numpy)

    @property
    def bounds(self):
        """(xmin, ymin, zmin, xmax, ymax, zmax) of the control net."""
        out = _arrays.out_array(6)
        call("projcurve_surface_bounds", self._ptr, out)
        return tuple(out[:6])

    def closest_point(self, p):
        """ClosestPoint(parameter (u, v), point, distance)."""
        p = _arrays.point(p, "p")
        uv, q, d = _arrays.out_array(2), _arrays.out_array(3), _dbl()
        call("projcurve_surface_closest_point", self._ptr, p.ptr, uv, q, ctypes.byref(d))
        return ClosestPoint(tuple(uv[:2]), tuple(q[:3]), d.value)

    def foot_points(self, p):
        """Every interior foot point (u, v) of p, nearest first."""
        p = _arrays.point(p, "p")
        count = _size()
        call("projcurve_surface_foot_points", self._ptr, p.ptr, 0, None, ctypes.byref(count))
        n = count.value
        uv = _arrays.out_array(2 * n)
        call("projcurve_surface_foot_points", self._ptr, p.ptr, n, uv, ctypes.byref(count))
        return _arrays.rows(uv, min(n, count.value), 2)

    def intersect_line(self, origin, direction, ray_only=False):
        """Every Hit(u, v, lam, flags) of origin + lam direction, by lam."""
        o, d = _arrays.point(origin, "origin"), _arrays.point(direction, "direction")
        count = _size()
        args = (self._ptr, o.ptr, d.ptr, 1 if ray_only else 0)
        call("projcurve_surface_intersect_line", *args, 0, None, None, ctypes.byref(count))
        n = count.value
        hits, flags = _arrays.out_array(3 * n), (ctypes.c_uint * max(n, 1))()
        call("projcurve_surface_intersect_line", *args, n, hits, flags, ctypes.byref(count))
        return [Hit(hits[3 * k], hits[3 * k + 1], hits[3 * k + 2], flags[k])
                for k in range(min(n, count.value))]


__all__ = ["Curve", "Surface", "SurfaceInfo", "CurveInfo", "ClosestPoint", "Hit"]
