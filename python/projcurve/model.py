# SPDX-License-Identifier: BSD-3-Clause
"""Models read from IGES, STEP and G+Smo XML files: their surfaces, curves,
faces (trimmed surfaces) and shapes (faces with shared edges)."""
import collections
import ctypes
import enum
import os

from . import _arrays
from . import _generated as gen
from ._errors import fail
from ._handle import Handle
from ._lib import call, fn, limits
from .geometry import Curve, Surface


def _enum(cname, prefix, name):
    return enum.IntEnum(name, {k[len(prefix):]: v for k, v in gen.ENUMS[cname].items()})


Where = _enum("projcurve_where", "PROJCURVE_", "Where")
ShapeKind = _enum("projcurve_shape_kind", "PROJCURVE_SHAPE_", "ShapeKind")

FacePiece = collections.namedtuple(
    "FacePiece", "degree control_points weights knots sense edge edge_sense flags")
FaceInfo = collections.namedtuple("FaceInfo", "same_sense periodic kind")
EdgeUse = collections.namedtuple("EdgeUse", "face loop piece sense")
Edge = collections.namedtuple("Edge", "id uses")

_size = ctypes.c_size_t
_int = ctypes.c_int
_dbl = ctypes.c_double
DoublePtr = ctypes.POINTER(ctypes.c_double)


class Face(Handle):
    """A surface with trimming loops: a model's (borrowed) or made with
    Face.create (it keeps its surface alive)."""
    _kind = "face"

    def __init__(self, ptr, owner=None, surface=None):
        if owner is None:
            super().__init__(ptr, fn["projcurve_face_destroy"], (surface,))
        else:
            super().__init__(ptr, None, (owner,))
        self._surface = surface

    @classmethod
    def create(cls, surface, loops=(), tol_uv=0.0):
        """loops: the outer loop first, then holes; each a list of pieces,
        each a dict with degree, control_points ((u, v) rows), knots and
        optionally weights. No loops: the whole domain."""
        n_loops = len(loops)
        pieces = [p for loop in loops for p in loop]
        n = max(len(pieces), 1)
        loop_pieces = (_size * max(n_loops, 1))(*[len(loop) for loop in loops])
        degrees, n_ctrl = (_int * n)(), (_size * n)()
        ctrl, weights, knots = (DoublePtr * n)(), (DoublePtr * n)(), (DoublePtr * n)()
        keep = []
        for j, p in enumerate(pieces):
            what = "loop piece %d" % j
            try:
                degree = _arrays.c_int(p["degree"], what + " degree", "BAD_DEGREE")
                c = _arrays.doubles(p["control_points"], what + " control_points", dim=2)
                k = _arrays.doubles(p["knots"], what + " knots")
            except (KeyError, TypeError):
                raise fail("INVALID_ARGUMENT", what + ": a dict with degree, control_points "
                           "and knots expected", "projcurve") from None
            m = c.n // 2
            if k.n != m + degree + 1:
                raise fail("BAD_COUNT", "%s knots: %d values, %d expected"
                           % (what, k.n, m + degree + 1), "projcurve")
            degrees[j], n_ctrl[j], ctrl[j], knots[j] = degree, m, c.ptr, k.ptr
            keep += [c, k]
            if p.get("weights") is not None:
                w = _arrays.doubles(p["weights"], what + " weights")
                if w.n != m:
                    raise fail("BAD_COUNT", "%s weights: %d values, %d expected"
                               % (what, w.n, m), "projcurve")
                weights[j] = w.ptr
                keep.append(w)
        out = ctypes.c_void_p()
        call("projcurve_face_create", surface._ptr, n_loops, loop_pieces, degrees, n_ctrl,
             ctrl, weights, knots, float(tol_uv), ctypes.byref(out))
        return cls(out.value, surface=surface)

    @property
    def surface(self):
        if self._surface is None:
            self._surface = Surface(fn["projcurve_face_surface"](self._ptr), owner=self)
        return self._surface

    @property
    def loops(self):
        """[[FacePiece, ...] per loop], the outer loop first."""
        out = []
        for loop in range(fn["projcurve_face_loop_count"](self._ptr)):
            count = _size()
            call("projcurve_face_loop_piece_count", self._ptr, loop, ctypes.byref(count))
            out.append([self._piece(loop, k) for k in range(count.value)])
        return out

    def _piece(self, loop, k):
        deg, n, sense = _int(), _size(), _int()
        c, w, kn = DoublePtr(), DoublePtr(), DoublePtr()
        call("projcurve_face_piece_curve", self._ptr, loop, k, ctypes.byref(deg), ctypes.byref(n),
             ctypes.byref(c), ctypes.byref(w), ctypes.byref(kn), ctypes.byref(sense))
        edge, esense, flags = ctypes.c_long(), _int(), ctypes.c_uint()
        call("projcurve_face_piece_edge", self._ptr, loop, k, ctypes.byref(edge),
             ctypes.byref(esense), ctypes.byref(flags))
        m = n.value
        ctrl = [(c[2 * i], c[2 * i + 1]) for i in range(m)]
        weights = [w[i] for i in range(m)] if w else None
        knots = [kn[i] for i in range(m + deg.value + 1)]
        return FacePiece(deg.value, ctrl, weights, knots, sense.value, edge.value, esense.value,
                         flags.value)

    def classify(self, u, v):
        where = _int()
        call("projcurve_face_classify", self._ptr, float(u), float(v), ctypes.byref(where))
        return Where(where.value)

    @property
    def bounds(self):
        """((u0, u1, v0, v1), (x0, y0, z0, x1, y1, z1))."""
        uv, box = _arrays.out_array(4), _arrays.out_array(6)
        call("projcurve_face_bounds", self._ptr, uv, box)
        return tuple(uv[:4]), tuple(box[:6])

    @property
    def tolerance(self):
        """(tol_uv, tol_model)."""
        a, b = _dbl(), _dbl()
        call("projcurve_face_tolerance", self._ptr, ctypes.byref(a), ctypes.byref(b))
        return a.value, b.value

    @property
    def info(self):
        same, periodic, kind = _int(), (_int * 2)(), ctypes.c_char_p()
        call("projcurve_face_info", self._ptr, ctypes.byref(same), periodic, ctypes.byref(kind))
        return FaceInfo(same.value, (bool(periodic[0]), bool(periodic[1])),
                        kind.value.decode() if kind.value else None)


class Shape(Handle):
    """A set of faces of a model with the edges they share (borrowed)."""
    _kind = "shape"

    def __init__(self, ptr, model):
        super().__init__(ptr, None, (model,))
        self.model = model

    @property
    def kind(self):
        k = _int()
        call("projcurve_shape_info", self._ptr, ctypes.byref(k), None)
        return ShapeKind(k.value)

    @property
    def sew_tolerance(self):
        t = _dbl()
        call("projcurve_shape_info", self._ptr, None, ctypes.byref(t))
        return t.value

    @property
    def faces(self):
        n = fn["projcurve_shape_face_count"](self._ptr)
        return [Face(fn["projcurve_shape_face"](self._ptr, k), owner=self) for k in range(n)]

    @property
    def face_model_indices(self):
        """The model's index of each of the shape's faces."""
        out = []
        for k in range(fn["projcurve_shape_face_count"](self._ptr)):
            m = _size()
            call("projcurve_shape_face_model_index", self._ptr, k, ctypes.byref(m))
            out.append(m.value)
        return out

    @property
    def edges(self):
        """[Edge(id, [EdgeUse(face, loop, piece, sense), ...]), ...] by id."""
        out = []
        for e in range(fn["projcurve_shape_edge_count"](self._ptr)):
            eid, n_uses = ctypes.c_long(), _size()
            call("projcurve_shape_edge", self._ptr, e, ctypes.byref(eid), ctypes.byref(n_uses))
            uses = []
            for u in range(n_uses.value):
                f, lo, pc, s = _size(), _size(), _size(), _int()
                call("projcurve_shape_edge_use", self._ptr, e, u, ctypes.byref(f), ctypes.byref(lo),
                     ctypes.byref(pc), ctypes.byref(s))
                uses.append(EdgeUse(f.value, lo.value, pc.value, s.value))
            out.append(Edge(eid.value, uses))
        return out


class Model(Handle):
    """A file read: Model.read(path) or Model.from_bytes(data). Its
    surfaces, curves, faces and shapes are borrowed: each keeps the model
    alive, and closing the model closes them."""
    _kind = "model"

    def __init__(self, ptr):
        super().__init__(ptr, fn["projcurve_model_destroy"])

    @classmethod
    def read(cls, path, max_control_points=None):
        """max_control_points: the size limit of each surface and curve
        read (None: DEFAULT_MAX_CONTROL_POINTS)."""
        out = ctypes.c_void_p()
        call("projcurve_model_read_file", os.fsencode(path), ctypes.byref(out),
             limits=limits(max_control_points))
        return cls(out.value)

    @classmethod
    def from_bytes(cls, data, max_control_points=None):
        if isinstance(data, str):
            data = data.encode()
        data = bytes(data)
        out = ctypes.c_void_p()
        call("projcurve_model_read_memory", data, len(data), ctypes.byref(out),
             limits=limits(max_control_points))
        return cls(out.value)

    def _list(self, count, get, make):
        p = self._ptr
        return [make(get(p, k), k) for k in range(fn[count](p))]

    @property
    def surfaces(self):
        return self._list("projcurve_model_surface_count", fn["projcurve_model_surface"],
                          lambda ptr, k: Surface(ptr, owner=self, kind=self._kind_of(k)))

    def _kind_of(self, k):
        kind = fn["projcurve_model_surface_kind"](self._ptr, k)
        return kind.decode() if kind else None

    @property
    def curves(self):
        return self._list("projcurve_model_curve_count", fn["projcurve_model_curve"],
                          lambda ptr, k: Curve(ptr, owner=self))

    @property
    def skipped(self):
        return self._list("projcurve_model_skipped_count", fn["projcurve_model_skipped"],
                          lambda s, k: s.decode("utf-8", "replace"))

    @property
    def faces(self):
        return self._list("projcurve_model_face_count", fn["projcurve_model_face"],
                          lambda ptr, k: Face(ptr, owner=self))

    @property
    def unbuilt_faces(self):
        """[(reason, surface kind), ...] of the faces the reader could not build."""
        p = self._ptr
        out = []
        for k in range(fn["projcurve_model_unbuilt_face_count"](p)):
            reason = fn["projcurve_model_unbuilt_face"](p, k)
            kind = fn["projcurve_model_unbuilt_face_kind"](p, k)
            out.append((reason.decode("utf-8", "replace"), kind.decode() if kind else None))
        return out

    @property
    def shapes(self):
        return self._list("projcurve_model_shape_count", fn["projcurve_model_shape"],
                          lambda ptr, k: Shape(ptr, self))

    @property
    def length_unit(self):
        """Metres per model unit as the file states it, or None."""
        m = _dbl()
        return m.value if fn["projcurve_model_length_unit"](self._ptr, ctypes.byref(m)) else None

    @property
    def precision(self):
        """The file's distance precision in model units, or None."""
        m = _dbl()
        return m.value if fn["projcurve_model_precision"](self._ptr, ctypes.byref(m)) else None


class IgesWriter(Handle):
    """Collects surfaces, curves and results, then writes one IGES 5.3 file."""
    _kind = "IGES writer"

    def __init__(self, length_unit=None):
        out = ctypes.c_void_p()
        call("projcurve_iges_writer_create", ctypes.byref(out))
        super().__init__(out.value, fn["projcurve_iges_writer_destroy"])
        if length_unit is not None:
            self.set_length_unit(length_unit)

    def add_surface(self, surface):
        call("projcurve_iges_writer_add_surface", self._ptr, surface._ptr)

    def add_curve(self, curve):
        call("projcurve_iges_writer_add_curve", self._ptr, curve._ptr)

    def add_result(self, surface, result, pieces=False):
        """Every branch of result (on surface): the compact curves, or with
        pieces=True the composed pieces joined."""
        name = ("projcurve_iges_writer_add_result_pieces" if pieces
                else "projcurve_iges_writer_add_result")
        call(name, self._ptr, surface._ptr, result._ptr)

    def add_shape_result(self, shape_result):
        """Every connected curve of a ShapeResult as one composite curve
        (entity 102) of its face pieces' 3D curves, in chain order."""
        call("projcurve_iges_writer_add_shape_result", self._ptr, shape_result._ptr)

    def set_length_unit(self, metres_per_unit):
        call("projcurve_iges_writer_set_length_unit", self._ptr, float(metres_per_unit))

    def write(self, path):
        call("projcurve_iges_writer_write", self._ptr, os.fsencode(path))


class StepWriter(Handle):
    """Collects surfaces, curves and results, then writes one STEP file
    (AP214): surfaces, curves and one SURFACE_CURVE per branch of a result."""
    _kind = "STEP writer"

    def __init__(self, length_unit=None, uncertainty=None):
        out = ctypes.c_void_p()
        call("projcurve_step_writer_create", ctypes.byref(out))
        super().__init__(out.value, fn["projcurve_step_writer_destroy"])
        if length_unit is not None:
            self.set_length_unit(length_unit)
        if uncertainty is not None:
            self.set_uncertainty(uncertainty)

    def add_surface(self, surface):
        call("projcurve_step_writer_add_surface", self._ptr, surface._ptr)

    def add_curve(self, curve):
        call("projcurve_step_writer_add_curve", self._ptr, curve._ptr)

    def add_result(self, surface, result):
        """Every branch of result (on surface) as a SURFACE_CURVE of its
        compact curve and pcurve."""
        call("projcurve_step_writer_add_result", self._ptr, surface._ptr, result._ptr)

    def add_shape_result(self, shape_result):
        """Every connected curve of a ShapeResult as one COMPOSITE_CURVE of
        its face pieces' 3D curves, in chain order."""
        call("projcurve_step_writer_add_shape_result", self._ptr, shape_result._ptr)

    def set_length_unit(self, metres_per_unit):
        call("projcurve_step_writer_set_length_unit", self._ptr, float(metres_per_unit))

    def set_uncertainty(self, distance):
        """The file's distance uncertainty in model units (no longer raised
        by add_result)."""
        call("projcurve_step_writer_set_uncertainty", self._ptr, float(distance))

    def write(self, path):
        call("projcurve_step_writer_write", self._ptr, os.fsencode(path))
