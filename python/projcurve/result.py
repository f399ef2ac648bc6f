# SPDX-License-Identifier: BSD-3-Clause
"""Projection calls and their results: branches with their traced points,
(u, v) points, 3D points, composed pieces and compact curves."""
import collections
import ctypes
import enum

from . import _arrays
from . import _generated as gen
from ._errors import Status, error_for, fail
from ._handle import Handle
from ._lib import CALLBACK_TYPES, Context, call, fn
from .geometry import Curve
from .options import Options


def _enum(cname, prefix, name):
    return enum.IntEnum(name, {k[len(prefix):]: v for k, v in gen.ENUMS[cname].items()})


BranchStart = _enum("projcurve_branch_start", "PROJCURVE_START_", "BranchStart")
BranchEnd = _enum("projcurve_branch_end", "PROJCURVE_END_", "BranchEnd")
Stat = _enum("projcurve_stat", "PROJCURVE_STAT_", "Stat")

Piece = collections.namedtuple(
    "Piece", "degree control_points weights t_range uv_range pcurve_degree pcurve_control_points")
CompactInfo = collections.namedtuple("CompactInfo", "pcurve_fitted pcurve_error curve_error")
# A jump of a branch's pcurve across a seam or a pole: at curve parameter t
# the (u, v) just after minus just before is (du, dv).
Seam = collections.namedtuple("Seam", "t du dv")

_MAX_PIECE = gen.DEFINES["PROJCURVE_MAX_PIECE_POINTS"]
_MAX_PCURVE = gen.DEFINES["PROJCURVE_MAX_PCURVE_POINTS"]
_size = ctypes.c_size_t


class Branch:
    """One branch of a Result (a view: it keeps the result alive)."""

    def __init__(self, result, index):
        self.result = result
        self.index = index
        t, st, en = _arrays.out_array(2), ctypes.c_int(), ctypes.c_int()
        n_pts, n_pcs = _size(), _size()
        call("projcurve_result_branch_info", result._ptr, index, t, ctypes.byref(st),
             ctypes.byref(en), ctypes.byref(n_pts), ctypes.byref(n_pcs))
        self.t_range = (t[0], t[1])
        self.start = BranchStart(st.value)
        self.end = BranchEnd(en.value)
        self.n_points = n_pts.value
        self.n_pieces = n_pcs.value

    def __repr__(self):
        return ("Branch(%d, t %r, %s -> %s, %d points, %d pieces)"
                % (self.index, self.t_range, self.start.name, self.end.name, self.n_points,
                   self.n_pieces))

    def _raw_points(self):
        count = _size()
        ptr = self.result._ptr
        call("projcurve_result_branch_points", ptr, self.index, 0, None, ctypes.byref(count))
        n = count.value
        dim = self.result.point_dim
        buf = _arrays.out_array(dim * n)
        call("projcurve_result_branch_points", ptr, self.index, n, buf, ctypes.byref(count))
        return buf, min(n, count.value), dim

    def tuv(self, numpy=False):
        """The traced points as (t, u, v) rows ((t, x, y, z) on an implicit
        surface)."""
        buf, n, dim = self._raw_points()
        return _arrays.rows(buf, n, dim, numpy)

    def t(self, numpy=False):
        buf, n, dim = self._raw_points()
        return _arrays.values((ctypes.c_double * max(n, 1))(*buf[0:dim * n:dim]), n, numpy)

    def uv(self, numpy=False):
        """The traced points in the surface's (u, v) domain."""
        if self.result.point_dim != 3:
            raise fail("INVALID_ARGUMENT", "a result on an implicit surface has no (u, v)",
                       "projcurve")
        buf, n, _ = self._raw_points()
        flat = _arrays.out_array(2 * n)
        for k in range(n):
            flat[2 * k], flat[2 * k + 1] = buf[3 * k + 1], buf[3 * k + 2]
        return _arrays.rows(flat, n, 2, numpy)

    def points(self, numpy=False):
        """The traced points in 3D: S(u, v) of each (u, v), or the (x, y, z)
        of an implicit result."""
        if self.result.point_dim == 4:
            buf, n, _ = self._raw_points()
            flat = _arrays.out_array(3 * n)
            for k in range(n):
                flat[3 * k:3 * k + 3] = buf[4 * k + 1:4 * k + 4]
            return _arrays.rows(flat, n, 3, numpy)
        return self.result.surface.points(self.uv(), numpy)

    @property
    def seams(self):
        """[Seam(t, du, dv), ...] in increasing t: where the pcurve jumps (a
        seam of a closed surface crossed, a pole passed); [] for none."""
        ptr = self.result._ptr
        count = _size()
        call("projcurve_result_branch_seam_count", ptr, self.index, ctypes.byref(count))
        t, du, dv = ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
        out = []
        for k in range(count.value):
            call("projcurve_result_branch_seam", ptr, self.index, k, ctypes.byref(t),
                 ctypes.byref(du), ctypes.byref(dv))
            out.append(Seam(t.value, du.value, dv.value))
        return out

    @property
    def pieces(self):
        """The composed pieces: Piece(degree, control_points, weights,
        t_range, uv_range, pcurve_degree, pcurve_control_points)."""
        out = []
        ptr = self.result._ptr
        implicit = self.result.point_dim == 4
        ctrl, w = _arrays.out_array(3 * _MAX_PIECE), _arrays.out_array(_MAX_PIECE)
        rng, uvr = _arrays.out_array(2), _arrays.out_array(4)
        uvc = _arrays.out_array(2 * _MAX_PCURVE)
        deg, pdeg = ctypes.c_int(), ctypes.c_int()
        for k in range(self.n_pieces):
            call("projcurve_result_piece", ptr, self.index, k, ctypes.byref(deg), ctrl, w, rng, uvr)
            d = deg.value
            pd, pc = None, None
            if not implicit:
                call("projcurve_result_piece_pcurve", ptr, self.index, k, ctypes.byref(pdeg), uvc)
                pd, pc = pdeg.value, _arrays.rows(uvc, pdeg.value + 1, 2)
            out.append(Piece(d, _arrays.rows(ctrl, d + 1, 3), list(w[:d + 1]), (rng[0], rng[1]),
                             tuple(uvr[:4]), pd, pc))
        return out

    def _curve(self, name):
        out = ctypes.c_void_p()
        call(name, self.result._ptr, self.index, ctypes.byref(out))
        return Curve(out.value)

    def curve(self):
        """The pieces joined as one NURBS Curve (exactly on the surface)."""
        return self._curve("projcurve_result_branch_curve")

    def compact_pcurve(self):
        """The compact pcurve: a Curve whose control points are (u, v, 0)."""
        return self._curve("projcurve_result_branch_compact_pcurve")

    def compact_curve(self):
        """The compact 3D Curve (within eps_D of the projection)."""
        return self._curve("projcurve_result_branch_compact_curve")

    def compact_exact(self, surface=None):
        """The compact pcurve composed with the surface exactly: one NURBS
        Curve on the surface to rounding, of degree 3 (p + q) for the
        cubic pcurve (rational when the surface or the pcurve is, as a
        circle's onto a plane, of degree 2 (p + q); above 25 on surfaces
        with p + q > 8, which Open CASCADE cannot read). Its Bezier parts
        are joined with knots of multiplicity the degree where they meet
        only C0 (seams, poles, creases of the pcurve or the surface) and
        of lower multiplicity where the curve is smoother (C2 at a simple
        knot of the pcurve inside a patch, C^(p - m) across a knot line of
        multiplicity m): the copies removed move it by at most 256 ulps of
        its size. surface: the one the result was projected onto (the
        default)."""
        s = self.result.surface if surface is None else surface
        out = ctypes.c_void_p()
        call("projcurve_result_branch_compact_exact", self.result._ptr, s._ptr, self.index,
             ctypes.byref(out))
        return Curve(out.value)

    def compact_info(self):
        fitted, pe, ce = ctypes.c_int(), ctypes.c_double(), ctypes.c_double()
        call("projcurve_result_branch_compact_info", self.result._ptr, self.index,
             ctypes.byref(fitted), ctypes.byref(pe), ctypes.byref(ce))
        return CompactInfo(bool(fitted.value), pe.value, ce.value)


class Result(Handle):
    """The result of a projection call. .status is Status.OK, or
    LIMIT_REACHED / CANCELLED for a partial result (with .message)."""
    _kind = "result"

    def __init__(self, ptr, surface, curve, status=Status.OK, message=""):
        super().__init__(ptr, fn["projcurve_result_destroy"])
        self.surface = surface  # kept: 3D points evaluate it
        self.curve = curve
        self.status = Status(status)
        self.message = message
        self._branches = None

    @property
    def branches(self):
        if self._branches is None:
            n = fn["projcurve_result_branch_count"](self._ptr)
            self._branches = [Branch(self, k) for k in range(n)]
        return self._branches

    @property
    def point_dim(self):
        return fn["projcurve_result_point_dim"](self._ptr)

    @property
    def failure_count(self):
        return fn["projcurve_result_failure_count"](self._ptr)

    def stat(self, key):
        """A statistic by name ("points", "pieces", "tol_distance", ...) or Stat."""
        if isinstance(key, str):
            try:
                key = Stat[key.upper()]
            except KeyError:
                raise fail("UNKNOWN_OPTION", "no statistic %r (statistics: %s)"
                           % (key, ", ".join(s.name.lower() for s in Stat)),
                           "projcurve") from None
        out = ctypes.c_double()
        call("projcurve_result_stat", self._ptr, int(key), ctypes.byref(out))
        return out.value

    @property
    def stats(self):
        return {s.name.lower(): self.stat(s) for s in Stat}


_PARTIAL = (Status.ERR_LIMIT_REACHED, Status.ERR_CANCELLED)


def _merged_options(options, option_values):
    """The Options of a call: the caller's, with the keywords' over them."""
    if options is None or option_values:
        opts = Options(**option_values)
        if options is not None:  # the caller's options, with the keywords' over them
            for k, v in options.items():
                if k not in option_values and v != Options.info(k).default:
                    opts.set(k, v)
            if options.progress is not None:
                opts.progress = options.progress
    else:
        opts = options
    opts.progress_error = None
    return opts


def _project(name, surface, curve, options, allow_partial, option_values, *args):
    opts = _merged_options(options, option_values)
    out = ctypes.c_void_p()
    with Context() as ctx:
        status = fn[name](ctx.ptr, *args, opts._ptr, ctypes.byref(out))
        message = ctx.message() if status != 0 else ""
    result = Result(out.value, surface, curve, status, message) if out.value else None
    if opts.progress_error is not None:
        err, opts.progress_error = opts.progress_error, None
        if result is not None:
            result.close()
        raise err
    if status == 0:
        return result
    if status in _PARTIAL and allow_partial:
        return result
    e = error_for(status, message, name)
    e.result = result  # the partial result of LIMIT_REACHED and CANCELLED, else None
    raise e


def project_directional(surface, curve, direction, options=None, *, allow_partial=False,
                        **option_values):
    """Every branch of the projection of curve onto surface along direction.
    options: an Options, and/or option values by name (tol_distance=1e-6).
    A limit or a cancel raises LimitReachedError / CancelledError whose
    .result is the partial result; allow_partial=True returns it instead
    (its .status tells)."""
    d = _arrays.point(direction, "direction")
    return _project("projcurve_project_directional", surface, curve, options, allow_partial,
                    option_values, surface._ptr, curve._ptr, d.ptr)


# Written by no call: tells a call that failed as a whole (statuses untouched).
_UNSET = -0x7fff


def _project_curves(name, surface, curves, direction, options, allow_partial, option_values):
    curves = list(curves)
    n = len(curves)
    opts = _merged_options(options, option_values)
    handles = (ctypes.c_void_p * max(n, 1))(*[c._ptr for c in curves])
    raw = (ctypes.c_void_p * max(n, 1))()
    statuses = (ctypes.c_int * max(n, 1))(*([_UNSET] * max(n, 1)))
    middle = (direction.ptr,) if direction is not None else ()
    with Context() as ctx:
        status = fn[name](ctx.ptr, surface._ptr, handles, n, *middle, opts._ptr, raw, statuses)
        message = ctx.message() if status != 0 else ""
    ran = n > 0 and statuses[0] != _UNSET
    results, codes = [], []
    for i in range(n if ran else 0):
        code = Status(statuses[i])
        codes.append(code)
        why = "" if code == Status.OK else fn["projcurve_status_string"](int(code)).decode()
        if message.startswith("curve %d: " % i):
            why = message[len("curve %d: " % i):]
        results.append(Result(raw[i], surface, curves[i], code, why) if raw[i] else None)
    if opts.progress_error is not None:
        err, opts.progress_error = opts.progress_error, None
        for r in results:
            if r is not None:
                r.close()
        raise err
    if status == 0:
        return results
    if ran and allow_partial and all(c == Status.OK or c in _PARTIAL for c in codes):
        return results
    e = error_for(status, message, name)
    e.results = results  # per curve: its Result, None where its call kept none ([]: none ran)
    e.statuses = codes
    raise e


def project_curves_directional(surface, curves, direction, options=None, *,
                               allow_partial=False, **option_values):
    """Many curves onto surface along direction in one call: a list with
    the Result of each curve, the same as project_directional gives it.
    threads=N (the option) shares the curves out among N threads; the
    results are the same bit for bit. A curve that fails raises the Error
    of the first such curve, whose .results (None where a curve kept no
    result) and .statuses give every curve's; allow_partial=True returns
    the list when the only failures are limits and cancels."""
    d = _arrays.point(direction, "direction")
    return _project_curves("projcurve_project_curves_directional", surface, curves, d, options,
                           allow_partial, option_values)


def project_curves_orthogonal(surface, curves, options=None, *, allow_partial=False,
                              **option_values):
    """Many curves orthogonally onto surface (see project_curves_directional)."""
    return _project_curves("projcurve_project_curves_orthogonal", surface, curves, None, options,
                           allow_partial, option_values)


def project_conical(surface, curve, eye, options=None, *, allow_partial=False, **option_values):
    """Every branch of the conical (central) projection of curve onto
    surface from the eye point eye: P(t) maps to the points of the surface
    on the ray from eye through P(t), beyond P(t) (see project_directional
    for options and partial results). A curve through the eye raises
    SingularError; an eye that is not finite NotFiniteError."""
    e = _arrays.point(eye, "eye")
    return _project("projcurve_project_conical", surface, curve, options, allow_partial,
                    option_values, surface._ptr, curve._ptr, e.ptr)


def project_orthogonal(surface, curve, options=None, *, allow_partial=False, **option_values):
    """Every branch of foot points of curve on surface (see
    project_directional for options and partial results)."""
    return _project("projcurve_project_orthogonal", surface, curve, options, allow_partial,
                    option_values, surface._ptr, curve._ptr)


def project_orthogonal_implicit(function, model_size, curve, options=None, *,
                                allow_partial=False, **option_values):
    """Orthogonal projection onto the implicit surface function(x) = 0:
    function((x, y, z)) -> (value, gradient[3], hessian[9] row-major). The
    result's points are (t, x, y, z)."""
    def trampoline(_user, x, value, grad, hess):
        try:
            f, g, h = function((x[0], x[1], x[2]))
            value[0] = float(f)
            g = [float(a) for a in g]
            h = [float(a) for row in h for a in (row if hasattr(row, "__len__") else [row])]
            if len(g) != 3 or len(h) != 9:
                return 1
            for i in range(3):
                grad[i] = g[i]
            for i in range(9):
                hess[i] = h[i]
            return 0
        except Exception:  # the library reports a callback failure
            return 1
    cb = CALLBACK_TYPES["projcurve_implicit_fn"](trampoline)
    return _project("projcurve_project_orthogonal_implicit", None, curve, options,
                    allow_partial, option_values, cb, None, float(model_size), curve._ptr)


__all__ = ["Branch", "Result", "Piece", "CompactInfo", "Seam", "BranchStart", "BranchEnd", "Stat",
           "project_curves_directional", "project_curves_orthogonal",
           "project_directional", "project_conical", "project_orthogonal",
           "project_orthogonal_implicit"]
