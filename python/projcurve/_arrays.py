# SPDX-License-Identifier: BSD-3-Clause
"""Arrays in and out: nested sequences or numpy arrays to C doubles, and C
doubles back to tuples or (when asked) numpy arrays. numpy is optional."""
import ctypes
import numbers

from ._errors import fail

try:
    import numpy as _np
except ImportError:  # the package works without it
    _np = None

DoublePtr = ctypes.POINTER(ctypes.c_double)

# Nesting deeper than this is not an array of points (a bound on the walk).
_MAX_DEPTH = 8


class Doubles:
    """Doubles ready for C: .ptr (double *), .n values, .shape; keeps the
    memory alive while it lives."""
    __slots__ = ("keep", "ptr", "n", "shape")

    def __init__(self, keep, ptr, n, shape):
        self.keep, self.ptr, self.n, self.shape = keep, ptr, n, shape


def _flatten(obj, what, depth, out):
    """Appends the numbers of a nested sequence to out; returns its shape."""
    if isinstance(obj, numbers.Real) and not isinstance(obj, bool):
        out.append(float(obj))
        return ()
    if depth >= _MAX_DEPTH or isinstance(obj, (str, bytes)):
        raise fail("INVALID_ARGUMENT", "%s: %r is not a number or a sequence of numbers"
                   % (what, obj), "projcurve")
    try:
        items = list(obj)
    except TypeError:
        raise fail("INVALID_ARGUMENT", "%s: %r is not a number or a sequence of numbers"
                   % (what, obj), "projcurve") from None
    shapes = {_flatten(item, what, depth + 1, out) for item in items}
    if len(shapes) > 1:
        raise fail("BAD_COUNT", "%s: rows of different lengths %s" % (what, sorted(shapes)),
                   "projcurve")
    return (len(items),) + (shapes.pop() if shapes else ())


def doubles(obj, what, dim=None):
    """obj (numbers, nested sequences, a numpy array) -> Doubles. With dim,
    the innermost length must be dim (points of dim coordinates)."""
    if _np is not None and isinstance(obj, _np.ndarray):
        if obj.dtype.kind not in "fiu":
            raise fail("INVALID_ARGUMENT", "%s: a numpy array of %s, not of numbers"
                       % (what, obj.dtype), "projcurve")
        a = _np.ascontiguousarray(obj, dtype=_np.float64)
        shape, keep, ptr = a.shape, a, a.ctypes.data_as(DoublePtr)
        n = int(a.size)
    else:
        values = []
        shape = _flatten(obj, what, 0, values)
        n = len(values)
        keep = (ctypes.c_double * max(n, 1))(*values)
        ptr = ctypes.cast(keep, DoublePtr)
    if dim is not None and n == 0:
        shape = (0, dim)  # no points at all
    if dim is not None and (len(shape) == 0 or shape[-1] != dim):
        raise fail("BAD_COUNT", "%s: points of %d coordinates expected, got shape %s"
                   % (what, dim, tuple(shape)), "projcurve")
    return Doubles(keep, ptr, n, tuple(shape))


def point(obj, what, dim=3):
    """One point -> a C double[dim]."""
    d = doubles(obj, what)
    if d.shape != (dim,):
        raise fail("BAD_COUNT", "%s: %d coordinates expected, got shape %s"
                   % (what, dim, d.shape), "projcurve")
    return d


def c_int(value, what, status="OUT_OF_RANGE"):
    """value as a C int; ctypes would wrap a larger one silently."""
    try:
        v = int(value)
    except (TypeError, ValueError):
        raise fail("INVALID_ARGUMENT", "%s: %r is not an integer" % (what, value),
                   "projcurve") from None
    if v != value or not -2 ** 31 <= v < 2 ** 31:
        raise fail(status, "%s: %r is not an int of C" % (what, value), "projcurve")
    return v


def out_array(n):
    return (ctypes.c_double * max(n, 1))()


def rows(buf, n_rows, dim, numpy=False, offset=0):
    """n_rows rows of dim doubles of buf -> a list of tuples or an array."""
    if numpy:
        if _np is None:
            raise ImportError("numpy=True needs numpy")
        flat = _np.ctypeslib.as_array(buf)[offset:offset + n_rows * dim]
        return flat.reshape(n_rows, dim).copy()
    start = offset
    return [tuple(buf[start + dim * k: start + dim * (k + 1)]) for k in range(n_rows)]


def values(buf, n, numpy=False):
    if numpy:
        if _np is None:
            raise ImportError("numpy=True needs numpy")
        return _np.ctypeslib.as_array(buf)[:n].copy()
    return list(buf[:n])

