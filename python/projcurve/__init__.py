# SPDX-License-Identifier: BSD-3-Clause
"""libprojcurve from Python: projections of curves onto B-spline and NURBS
surfaces.

    import projcurve as pc
    s = pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                              control_points=[[0,0,0], [1,0,0], [0,1,0], [1,1,1]],
                              knots=([0,0,1,1], [0,0,1,1]))
    c = pc.Curve.from_nurbs(degree=1, control_points=[[0.1,0.2,2], [0.9,0.7,2]],
                            knots=[0,0,1,1])
    res = pc.project_directional(s, c, (0, 0, -1))
    res.branches[0].points()

Every failure raises projcurve.Error (a subclass per status, e.g.
ZeroDirectionError) carrying .status and the library's .message. The
library is PROJCURVE_LIBRARY when set, else the one next to this package,
else the one of the prefix the package is installed in, else the dynamic
loader's. See docs/python.md.
"""
from . import _generated
from ._errors import ERROR_CLASSES, Error, Status
from ._lib import SONAME, fn as _fn, path as _path
from .geometry import ClosestPoint, Curve, CurveInfo, Hit, Surface, SurfaceInfo
from .model import (Edge, EdgeUse, Face, FaceInfo, FacePiece, IgesWriter, Model, Shape,
                    ShapeKind, StepWriter, Where)
from .shapeproj import (ConnectedCurve, FaceResult, ProjectionKind, ShapePiece, ShapeResult,
                        project_face, project_shape)
from .options import Option, OptionInfo, OptionType, Options, option_table
from .result import (Branch, BranchEnd, BranchStart, CompactInfo, Piece, Result, Seam, Stat,
                     project_conical, project_curves_directional, project_curves_orthogonal,
                     project_directional, project_orthogonal, project_orthogonal_implicit)

__version__ = _generated.VERSION

# The header's numeric #defines without their prefix: MAX_DEGREE, METHOD_RK4, ...
for _k, _v in _generated.DEFINES.items():
    globals()[_k[len("PROJCURVE_"):]] = _v

# ZeroDirectionError, BadKnotsError, ...: one per failure status.
for _cls in ERROR_CLASSES.values():
    globals()[_cls.__name__] = _cls


def library_path():
    """The path of the libprojcurve that was loaded."""
    return _path


def library_version():
    """The loaded library's version string (e.g. "1.6.0")."""
    return _fn["projcurve_version_string"]().decode()


def status_string(status):
    """The library's short name of a status."""
    return _fn["projcurve_status_string"](int(status)).decode()


__all__ = ["Error", "Status", "Surface", "Curve", "Model", "Face", "Shape", "Options",
           "Option", "OptionType", "OptionInfo", "Result", "Branch", "Piece", "IgesWriter",
           "StepWriter", "project_directional", "project_conical", "project_curves_directional",
           "project_curves_orthogonal", "Seam", "project_face", "project_shape",
           "ShapeResult", "ShapePiece", "ConnectedCurve", "FaceResult", "ProjectionKind", "project_orthogonal", "project_orthogonal_implicit",
           "BranchStart", "BranchEnd", "Stat", "Where", "ShapeKind", "library_path",
           "library_version", "status_string", "option_table"] + \
          [c.__name__ for c in ERROR_CLASSES.values()]
