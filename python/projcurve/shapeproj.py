# SPDX-License-Identifier: BSD-3-Clause
"""Projection onto faces (trimmed surfaces) and shapes: per face a Result
clipped to its loops, and the face pieces chained across shared edges into
connected curves."""
import collections
import ctypes
import enum

from . import _arrays
from . import _generated as gen
from ._errors import Status, error_for, fail
from ._handle import Handle
from ._lib import Context, call, fn
from .result import Branch, BranchEnd, BranchStart, Result, _PARTIAL, _merged_options

ProjectionKind = enum.IntEnum("ProjectionKind", {
    k[len("PROJCURVE_PROJECT_"):]: v for k, v in gen.ENUMS["projcurve_projection_kind"].items()})

# One face piece of a connected curve: the index of its face in the shape,
# its branch of that face's Result, its t range and start / end reasons.
ShapePiece = collections.namedtuple("ShapePiece", "face branch t_range start end")
ConnectedCurve = collections.namedtuple("ConnectedCurve", "pieces t_range closed")
# A projected face: its index in the shape, its Result (None when its
# projection failed), the status and message of its projection.
FaceResult = collections.namedtuple("FaceResult", "face result status message")

_size = ctypes.c_size_t


class _FaceResult(Result):
    """A face's result inside a ShapeResult (borrowed: keeps it alive)."""

    def __init__(self, ptr, owner, surface):
        Handle.__init__(self, ptr, None, (owner,))
        self.surface = surface
        self.curve = owner.curve
        self.status = Status.OK
        self.message = ""
        self._branches = None


class ShapeResult(Handle):
    """The result of project_face / project_shape. .status is Status.OK, or
    LIMIT_REACHED / CANCELLED for a partial result (with .message)."""
    _kind = "shape result"

    def __init__(self, ptr, surfaces, curve, status=Status.OK, message=""):
        super().__init__(ptr, fn["projcurve_shape_result_destroy"])
        self._surfaces = surfaces  # the face surfaces, by index in the shape
        self.curve = curve
        self.status = Status(status)
        self.message = message
        self._results = {}

    def _result(self, ptr, face):
        if ptr not in self._results:
            self._results[ptr] = _FaceResult(ptr, self, self._surfaces[face])
        return self._results[ptr]

    @property
    def faces(self):
        """[FaceResult(face, result, status, message), ...] of the faces
        projected, in the order of the shape."""
        out = []
        face, res = _size(), ctypes.c_void_p()
        st, msg = ctypes.c_int(), ctypes.c_char_p()
        for i in range(fn["projcurve_shape_result_face_count"](self._ptr)):
            call("projcurve_shape_result_face", self._ptr, i, ctypes.byref(face),
                 ctypes.byref(res), ctypes.byref(st), ctypes.byref(msg))
            r = self._result(res.value, face.value) if res.value else None
            out.append(FaceResult(face.value, r, Status(st.value),
                                  (msg.value or b"").decode("utf-8", "replace")))
        return out

    @property
    def curves(self):
        """[ConnectedCurve(pieces, t_range, closed), ...], each piece a
        ShapePiece(face, branch, t_range, start, end)."""
        out = []
        ptr = self._ptr
        n, closed, rng = _size(), ctypes.c_int(), _arrays.out_array(2)
        face, res, branch = _size(), ctypes.c_void_p(), _size()
        prng, st, en = _arrays.out_array(2), ctypes.c_int(), ctypes.c_int()
        for k in range(fn["projcurve_shape_result_curve_count"](ptr)):
            call("projcurve_shape_result_curve_info", ptr, k, ctypes.byref(n), rng,
                 ctypes.byref(closed))
            pieces = []
            for j in range(n.value):
                call("projcurve_shape_result_piece", ptr, k, j, ctypes.byref(face),
                     ctypes.byref(res), ctypes.byref(branch), prng, ctypes.byref(st),
                     ctypes.byref(en))
                b = Branch(self._result(res.value, face.value), branch.value)
                pieces.append(ShapePiece(face.value, b, (prng[0], prng[1]),
                                         BranchStart(st.value), BranchEnd(en.value)))
            out.append(ConnectedCurve(pieces, (rng[0], rng[1]), bool(closed.value)))
        return out

    @property
    def open_end_count(self):
        return fn["projcurve_shape_result_open_end_count"](self._ptr)

    @property
    def chain_tolerance(self):
        return fn["projcurve_shape_result_chain_tolerance"](self._ptr)


def _kind_and_vector(direction, eye):
    if direction is not None and eye is not None:
        raise fail("INVALID_ARGUMENT", "give a direction or an eye point, not both", "projcurve")
    if direction is not None:
        return ProjectionKind.DIRECTIONAL, _arrays.point(direction, "direction")
    if eye is not None:
        return ProjectionKind.CONICAL, _arrays.point(eye, "eye")
    return ProjectionKind.ORTHOGONAL, None


def _project_onto(name, target, surfaces, curve, direction, eye, options, allow_partial,
                  option_values):
    kind, vec = _kind_and_vector(direction, eye)
    opts = _merged_options(options, option_values)
    out = ctypes.c_void_p()
    with Context() as ctx:
        status = fn[name](ctx.ptr, target._ptr, curve._ptr, int(kind),
                          vec.ptr if vec is not None else None, opts._ptr, ctypes.byref(out))
        message = ctx.message() if status != 0 else ""
    result = ShapeResult(out.value, surfaces, curve, status, message) if out.value else None
    if status == 0 or (status in _PARTIAL and allow_partial):
        return result
    e = error_for(status, message, name)
    e.result = result
    raise e


def project_face(face, curve, direction=None, options=None, *, eye=None, allow_partial=False,
                 **option_values):
    """The projection of curve onto face (its surface's, clipped to its
    loops): along direction, from eye (conical), or orthogonal when
    neither is given. A ShapeResult with one face (index 0) whose
    connected curves are its branches."""
    return _project_onto("projcurve_project_face", face, [face.surface], curve, direction, eye,
                         options, allow_partial, option_values)


def project_shape(shape, curve, direction=None, options=None, *, eye=None, allow_partial=False,
                  **option_values):
    """The projection of curve onto every face of shape it can reach,
    chained across the shape's edges into connected curves (see
    project_face for direction / eye)."""
    surfaces = [f.surface for f in shape.faces]
    return _project_onto("projcurve_project_shape", shape, surfaces, curve, direction, eye,
                         options, allow_partial, option_values)


__all__ = ["ProjectionKind", "ShapePiece", "ConnectedCurve", "FaceResult", "ShapeResult",
           "project_face", "project_shape"]
