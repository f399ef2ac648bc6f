# SPDX-License-Identifier: BSD-3-Clause
"""The package's projection against the same call made in C: c_reference
(tests/python/c_reference.c, built in the tree, public API only) prints
every number of the result as a %a hexadecimal float; the package's
numbers must be the same doubles, bit for bit. Once with the model's own
surface and curve, once with handles the package builds from the arrays
it read back (lists and numpy): the arrays cross the FFI unchanged."""
import os
import struct
import subprocess

import pytest

from conftest import data

CASES = [
    ("cases/bumpy_bicubic_8x8_down.igs", ("dir", "0", "0", "-1"), "0.001"),
    ("cases/nurbs_half_cylinder_down.igs", ("dir", "0", "0", "-1"), "0.001"),
    ("cases/ortho_bumpy_bicubic_hover.igs", ("ortho",), "0.001"),
    # conical: an eye above the middle of the bumpy surface, the curve between
    ("cases/bumpy_bicubic_8x8_down.igs", ("eye", "50", "40", "120"), "0.001"),
]


def c_lines(path, mode, tol):
    exe = os.environ.get("PROJCURVE_C_REFERENCE")
    if not exe or not os.path.exists(exe):
        pytest.skip("PROJCURVE_C_REFERENCE (the c_reference program) not given")
    out = subprocess.run([exe, path, *mode, tol], check=True, capture_output=True, text=True,
                         timeout=120).stdout
    return [line.split() for line in out.splitlines()]


def bits(x):
    return struct.pack("<d", x)


def same(c_line, py_line):
    """A line of c_reference against the package's: names and counts as
    ints, every other token a double compared by its bits."""
    if len(c_line) != len(py_line):
        return False
    for c, p in zip(c_line, py_line):
        if isinstance(p, float):
            if bits(float.fromhex(c)) != bits(p):
                return False
        elif c != str(p):
            return False
    return True


def flat(rows):
    return [float(x) for row in rows for x in row]


def curve_line(name, b, curve):
    return [name, b] + flat(curve.control_points()) + [float(k) for k in curve.knots()]


def package_lines(pc, res):
    lines = []
    for b in res.branches:
        lines.append(["branch", b.index, b.t_range[0], b.t_range[1], int(b.start), int(b.end),
                      b.n_points, b.n_pieces])
        lines.append(["tuv", b.index] + flat(b.tuv()))
        for k, piece in enumerate(b.pieces):
            lines.append(["piece", b.index, k, piece.degree] + flat(piece.control_points)
                         + piece.weights + list(piece.t_range) + list(piece.uv_range))
        for name, get in (("compact_curve", b.compact_curve), ("compact_pcurve", b.compact_pcurve)):
            try:
                lines.append(curve_line(name, b.index, get()))
            except pc.Error:
                pass  # c_reference skips it too
    for s in pc.Stat:
        lines.append(["stat", int(s), res.stat(s)])
    return lines


def project(pc, surface, curve, mode, tol):
    if mode[0] == "dir":
        return pc.project_directional(surface, curve, [float(x) for x in mode[1:]],
                                      tol_distance=float(tol))
    if mode[0] == "eye":
        return pc.project_conical(surface, curve, [float(x) for x in mode[1:]],
                                  tol_distance=float(tol))
    return pc.project_orthogonal(surface, curve, tol_distance=float(tol))


def rebuilt(pc, surface, curve, numpy):
    conv = (lambda x: x)
    if numpy:
        np = pytest.importorskip("numpy")
        conv = np.asarray
    s = pc.Surface.from_nurbs(surface.degree, surface.shape,
                              conv(surface.control_points(numpy=numpy)),
                              tuple(conv(k) for k in surface.knots(numpy=numpy)),
                              conv(surface.weights(numpy=numpy)) if surface.rational else None)
    c = pc.Curve.from_nurbs(curve.degree, conv(curve.control_points(numpy=numpy)),
                            conv(curve.knots(numpy=numpy)),
                            conv(curve.weights(numpy=numpy)) if curve.rational else None)
    return s, c


def check(expected, got):
    assert len(expected) == len(got)
    for c_line, py_line in zip(expected, got):
        assert same(c_line, py_line), "%s %s..." % (c_line[0], c_line[1:4])


@pytest.mark.parametrize("case,mode,tol", CASES)
def test_model_handles_match_c(pc, case, mode, tol):
    expected = c_lines(data(case), mode, tol)
    assert expected and expected[0][0] == "branch"
    m = pc.Model.read(data(case))
    check(expected, package_lines(pc, project(pc, m.surfaces[0], m.curves[0], mode, tol)))


@pytest.mark.parametrize("numpy", [False, True])
@pytest.mark.parametrize("case,mode,tol", CASES)
def test_rebuilt_handles_match_c(pc, case, mode, tol, numpy):
    expected = c_lines(data(case), mode, tol)
    m = pc.Model.read(data(case))
    s, c = rebuilt(pc, m.surfaces[0], m.curves[0], numpy)
    check(expected, package_lines(pc, project(pc, s, c, mode, tol)))
