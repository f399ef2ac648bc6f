#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Drive the installed libprojcurve.so through ctypes, as an FFI user would.

Usage:
    test_ctypes.py LIBRARY                 # a path to libprojcurve.so.1
    test_ctypes.py --install CMAKE BUILD   # install BUILD into a temporary
                                           # prefix first and use that library

Only the standard library is used. The declarations below mirror
include/projcurve.h; the test checks the values an FFI binding depends on
(status codes, version, option bounds) and reads the context message after
each bad call. The geometry part passes Python arrays: it creates a NURBS
surface and curve, evaluates them against the Bernstein form computed here,
projects the curve along -z, reads the result back (traced points and the
composed curve, judged against the exact projection) and reads the message
after calls with bad arrays.
"""
import ctypes
import glob
import math
import os
import subprocess
import sys
import tempfile

# Status codes from projcurve.h that this test uses.
OK = 0
ERR_NULL_ARGUMENT = 1
ERR_OUT_OF_RANGE = 3
ERR_UNKNOWN_OPTION = 4
ERR_NOT_FINITE = 5
ERR_BAD_KNOTS = 6
ERR_BAD_COUNT = 7
ERR_BAD_WEIGHT = 8
ERR_INDEX = 22
ERR_VERSION = 14
ERR_WRONG_KIND = 23

OPT_TOL_DISTANCE = 1
OPT_TOL_ANGLE_DEG = 2
OPT_NEWTON_MAX_ITER = 4
OPT_MAX_POINTS = 8
OPTION_DOUBLE = 0
OPTION_INTEGER = 1

failures = 0


def check(condition, what):
    global failures
    if not condition:
        failures += 1
        print("FAIL:", what)


def bind(lib):
    """Declares argument and result types: without them ctypes would pass
    doubles and 64-bit integers wrongly."""
    c_status = ctypes.c_int
    ctx_p = ctypes.c_void_p
    opts_p = ctypes.c_void_p
    sigs = {
        "projcurve_version_number": (ctypes.c_uint, []),
        "projcurve_version_string": (ctypes.c_char_p, []),
        "projcurve_status_string": (ctypes.c_char_p, [c_status]),
        "projcurve_context_create": (c_status, [ctypes.c_uint, ctypes.POINTER(ctx_p)]),
        "projcurve_context_destroy": (None, [ctx_p]),
        "projcurve_context_message": (ctypes.c_char_p, [ctx_p]),
        "projcurve_context_status": (c_status, [ctx_p]),
        "projcurve_context_clear": (None, [ctx_p]),
        "projcurve_options_create": (c_status, [ctx_p, ctypes.POINTER(opts_p)]),
        "projcurve_options_destroy": (None, [opts_p]),
        "projcurve_option_info": (c_status, [ctx_p, ctypes.c_int, ctypes.POINTER(ctypes.c_int),
                                             ctypes.POINTER(ctypes.c_double),
                                             ctypes.POINTER(ctypes.c_double),
                                             ctypes.POINTER(ctypes.c_double)]),
        "projcurve_options_set_double": (c_status, [ctx_p, opts_p, ctypes.c_int, ctypes.c_double]),
        "projcurve_options_set_int": (c_status, [ctx_p, opts_p, ctypes.c_int, ctypes.c_longlong]),
        "projcurve_options_get_double": (c_status, [ctx_p, opts_p, ctypes.c_int,
                                                    ctypes.POINTER(ctypes.c_double)]),
        "projcurve_options_get_int": (c_status, [ctx_p, opts_p, ctypes.c_int,
                                                 ctypes.POINTER(ctypes.c_longlong)]),
    }
    dbl_p = ctypes.POINTER(ctypes.c_double)
    size = ctypes.c_size_t
    handle_out = ctypes.POINTER(ctypes.c_void_p)
    sigs.update({
        "projcurve_surface_create_nurbs": (c_status, [ctx_p, ctypes.c_int, ctypes.c_int, size, size,
                                                      dbl_p, dbl_p, dbl_p, dbl_p, handle_out]),
        "projcurve_surface_destroy": (None, [ctypes.c_void_p]),
        "projcurve_surface_eval": (c_status, [ctx_p, ctypes.c_void_p, ctypes.c_double,
                                              ctypes.c_double, ctypes.c_int, dbl_p]),
        "projcurve_curve_create_nurbs": (c_status, [ctx_p, ctypes.c_int, size, dbl_p, dbl_p,
                                                    dbl_p, handle_out]),
        "projcurve_curve_destroy": (None, [ctypes.c_void_p]),
        "projcurve_curve_domain": (c_status, [ctx_p, ctypes.c_void_p, dbl_p, dbl_p]),
        "projcurve_curve_eval": (c_status, [ctx_p, ctypes.c_void_p, ctypes.c_double, ctypes.c_int,
                                            dbl_p]),
        "projcurve_project_directional": (c_status, [ctx_p, ctypes.c_void_p, ctypes.c_void_p,
                                                     dbl_p, opts_p, handle_out]),
        "projcurve_result_destroy": (None, [ctypes.c_void_p]),
        "projcurve_result_branch_count": (size, [ctypes.c_void_p]),
        "projcurve_result_branch_info": (c_status, [ctx_p, ctypes.c_void_p, size, dbl_p,
                                                    ctypes.POINTER(ctypes.c_int),
                                                    ctypes.POINTER(ctypes.c_int),
                                                    ctypes.POINTER(size), ctypes.POINTER(size)]),
        "projcurve_result_branch_points": (c_status, [ctx_p, ctypes.c_void_p, size, size, dbl_p,
                                                      ctypes.POINTER(size)]),
        "projcurve_result_branch_curve": (c_status, [ctx_p, ctypes.c_void_p, size, handle_out]),
    })
    for name, (restype, argtypes) in sigs.items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes


def message(lib, ctx):
    return lib.projcurve_context_message(ctx).decode()


def run(lib_path):
    lib = ctypes.CDLL(lib_path)
    bind(lib)

    version = lib.projcurve_version_string().decode()
    number = lib.projcurve_version_number()
    major, minor, patch = (int(x) for x in version.split("."))
    check(number == major * 10000 + minor * 100 + patch, "version number %d vs %s" % (number, version))
    check(lib.projcurve_status_string(OK) == b"ok", "status string of OK")
    check(lib.projcurve_status_string(ERR_VERSION) == b"version mismatch", "status string of VERSION")
    check(lib.projcurve_status_string(-3) == b"unknown status", "status string of -3")

    ctx = ctypes.c_void_p()
    check(lib.projcurve_context_create(major + 1, ctypes.byref(ctx)) == ERR_VERSION,
          "wrong major version must be refused")
    check(ctx.value is None, "context untouched after a refused create")
    check(lib.projcurve_context_create(major, None) == ERR_NULL_ARGUMENT, "NULL out pointer")
    check(lib.projcurve_context_create(major, ctypes.byref(ctx)) == OK, "context create")
    check(message(lib, ctx) == "", "fresh context has no message")
    check(lib.projcurve_context_message(None) == b"no context", "NULL context message")

    opts = ctypes.c_void_p()
    check(lib.projcurve_options_create(ctx, ctypes.byref(opts)) == OK, "options create")

    # Bounds as an FFI binding would discover them.
    kind = ctypes.c_int(-1)
    lo, hi, default = ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
    check(lib.projcurve_option_info(ctx, OPT_MAX_POINTS, ctypes.byref(kind), ctypes.byref(lo),
                                    ctypes.byref(hi), ctypes.byref(default)) == OK, "option info")
    check(kind.value == OPTION_INTEGER and lo.value == 16 and hi.value == 2.0 ** 40
          and default.value == 1e5, "MAX_POINTS info %r" % ((kind.value, lo.value, hi.value, default.value),))

    # 64-bit integers pass intact.
    check(lib.projcurve_options_set_int(ctx, opts, OPT_MAX_POINTS, 2 ** 40) == OK, "set 2^40")
    got = ctypes.c_longlong()
    check(lib.projcurve_options_get_int(ctx, opts, OPT_MAX_POINTS, ctypes.byref(got)) == OK
          and got.value == 2 ** 40, "get 2^40")

    # Each bad call: its status, and a message that says what was wrong.
    bad_calls = [
        (lambda: lib.projcurve_options_set_double(ctx, opts, OPT_TOL_ANGLE_DEG, 91.0),
         ERR_OUT_OF_RANGE, "TOL_ANGLE_DEG"),
        (lambda: lib.projcurve_options_set_double(ctx, opts, OPT_TOL_ANGLE_DEG, math.nan),
         ERR_NOT_FINITE, "not finite"),
        (lambda: lib.projcurve_options_set_int(ctx, opts, 4242, 1), ERR_UNKNOWN_OPTION, "4242"),
        (lambda: lib.projcurve_options_set_double(ctx, opts, OPT_NEWTON_MAX_ITER, 3.0),
         ERR_WRONG_KIND, "integer"),
        (lambda: lib.projcurve_options_set_int(ctx, None, OPT_NEWTON_MAX_ITER, 3),
         ERR_NULL_ARGUMENT, "NULL"),
        (lambda: lib.projcurve_options_set_int(ctx, opts, OPT_NEWTON_MAX_ITER, 0),
         ERR_OUT_OF_RANGE, "outside [1, 200]"),
    ]
    for call, expected, fragment in bad_calls:
        lib.projcurve_context_clear(ctx)
        status = call()
        text = message(lib, ctx)
        print("  %-20s %s" % (lib.projcurve_status_string(status).decode() + ":", text))
        check(status == expected, "status %d, expected %d (%s)" % (status, expected, text))
        check(lib.projcurve_context_status(ctx) == expected, "context status after bad call")
        check(fragment in text, "message %r lacks %r" % (text, fragment))

    angle = ctypes.c_double()
    check(lib.projcurve_options_get_double(ctx, opts, OPT_TOL_ANGLE_DEG, ctypes.byref(angle)) == OK
          and angle.value == 1.0, "rejected values leave the option at its default")

    run_geometry(lib, ctx, opts)

    lib.projcurve_options_destroy(opts)
    lib.projcurve_context_destroy(ctx)
    lib.projcurve_context_destroy(None)


def doubles(values):
    return (ctypes.c_double * len(values))(*values)


def bernstein(n, i, s):
    return math.comb(n, i) * s ** i * (1.0 - s) ** (n - i)


# A biquadratic Bezier patch over [0, 1]^2 with x = u and y = v (control
# points on the uniform grid: linear precision) and heights Z[j][i] (v index
# j, u index i), and a quadratic Bezier curve above it.
Z = [[0.0, 0.3, 0.1], [0.2, 0.9, 0.4], [0.1, 0.5, 0.0]]
CURVE = [(0.1, 0.2, 2.0), (0.5, 0.9, 2.5), (0.9, 0.3, 2.0)]


def patch_z(u, v):
    return sum(bernstein(2, i, u) * bernstein(2, j, v) * Z[j][i]
               for i in range(3) for j in range(3))


def patch_z_u(u, v):
    """dz/du: the derivative of the Bernstein sum (degree-1 differences)."""
    return sum(2 * bernstein(1, i, u) * (Z[j][i + 1] - Z[j][i]) * bernstein(2, j, v)
               for i in range(2) for j in range(3))


def curve_point(t):
    return [sum(bernstein(2, i, t) * CURVE[i][k] for i in range(3)) for k in range(3)]


def exact_projection(t):
    x, y, _ = curve_point(t)
    return [x, y, patch_z(x, y)]


def distance_to_exact(p, t, half_width):
    """Distance from p to the exact projected curve near parameter t: a
    ternary search on the squared distance over [t - w, t + w] (one
    minimum there, the curve being smooth and w small)."""
    def d2(s):
        e = exact_projection(s)
        return sum((a - b) ** 2 for a, b in zip(p, e))
    lo, hi = max(0.0, t - half_width), min(1.0, t + half_width)
    for _ in range(100):
        m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        if d2(m1) < d2(m2):
            hi = m2
        else:
            lo = m1
    return math.sqrt(d2(0.5 * (lo + hi)))


def run_geometry(lib, ctx, opts):
    """Arrays in, geometry out, through the same calls a binding makes."""
    ctrl = []
    for j in range(3):
        for i in range(3):  # u fastest
            ctrl += [i / 2.0, j / 2.0, Z[j][i]]
    knots = doubles([0, 0, 0, 1, 1, 1])
    surface, curve, result, branch = (ctypes.c_void_p() for _ in range(4))
    check(lib.projcurve_surface_create_nurbs(ctx, 2, 2, 3, 3, doubles(ctrl), None, knots, knots,
                                             ctypes.byref(surface)) == OK,
          "surface create: " + message(lib, ctx))
    check(lib.projcurve_curve_create_nurbs(ctx, 2, 3, doubles([c for p in CURVE for c in p]),
                                           doubles([1.0, 1.0, 1.0]), knots,
                                           ctypes.byref(curve)) == OK,
          "curve create: " + message(lib, ctx))
    if not surface.value or not curve.value:
        return
    # Evaluation against the Bernstein form, to rounding (1e-14 on values of
    # order 1).
    out = (ctypes.c_double * 9)()
    for u, v in ((0.0, 0.0), (0.25, 0.7), (0.6, 0.15), (1.0, 1.0)):
        check(lib.projcurve_surface_eval(ctx, surface, u, v, 1, out) == OK, "surface eval")
        expected = [u, v, patch_z(u, v), 1.0, 0.0, patch_z_u(u, v)]
        check(all(abs(a - b) <= 1e-14 for a, b in zip(out[:6], expected)),
              "S, S_u at (%g, %g): %r, expected %r" % (u, v, list(out[:6]), expected))
    for t in (0.0, 0.3, 1.0):
        check(lib.projcurve_curve_eval(ctx, curve, t, 0, out) == OK, "curve eval")
        expected = curve_point(t)
        check(all(abs(a - b) <= 1e-14 for a, b in zip(out[:3], expected)),
              "C(%g): %r, expected %r" % (t, list(out[:3]), expected))

    # Projection along -z: one branch over the whole curve.
    tol = 1e-6
    check(lib.projcurve_options_set_double(ctx, opts, OPT_TOL_DISTANCE, tol) == OK, "set eps_D")
    status = lib.projcurve_project_directional(ctx, surface, curve, doubles([0.0, 0.0, -1.0]), opts,
                                               ctypes.byref(result))
    check(status == OK, "projection: %d %s" % (status, message(lib, ctx)))
    check(lib.projcurve_result_branch_count(result) == 1, "one branch")
    t_range = (ctypes.c_double * 2)()
    n_points, n_pieces = ctypes.c_size_t(), ctypes.c_size_t()
    check(lib.projcurve_result_branch_info(ctx, result, 0, t_range, None, None,
                                           ctypes.byref(n_points), ctypes.byref(n_pieces)) == OK,
          "branch info")
    check(min(t_range) == 0.0 and max(t_range) == 1.0, "t range %r" % list(t_range))
    # The traced points, in an array sized from a first call that asks for
    # the count: each (t, u, v) is the projection of C(t), so u, v are C's
    # x, y; to eps_D / 1000 (traced points are corrected far below eps_D).
    count = ctypes.c_size_t()
    check(lib.projcurve_result_branch_points(ctx, result, 0, 0, None, ctypes.byref(count)) == OK,
          "point count")
    check(count.value == n_points.value and count.value >= 2, "%d points" % count.value)
    tuv = (ctypes.c_double * (3 * count.value))()
    check(lib.projcurve_result_branch_points(ctx, result, 0, count.value, tuv,
                                             ctypes.byref(count)) == OK, "points")
    worst = max(math.hypot(tuv[3 * k + 1] - curve_point(tuv[3 * k])[0],
                           tuv[3 * k + 2] - curve_point(tuv[3 * k])[1])
                for k in range(count.value))
    check(worst <= tol * 1e-3, "traced points off the projection by %g" % worst)
    # The composed curve is within eps_D of the exact projection.
    check(n_pieces.value >= 1, "composed pieces")
    check(lib.projcurve_result_branch_curve(ctx, result, 0, ctypes.byref(branch)) == OK,
          "branch curve: " + message(lib, ctx))
    if branch.value:
        t0, t1 = ctypes.c_double(), ctypes.c_double()
        check(lib.projcurve_curve_domain(ctx, branch, ctypes.byref(t0), ctypes.byref(t1)) == OK,
              "branch domain")
        gap = 0.0
        for k in range(33):
            t = t0.value + (t1.value - t0.value) * k / 32.0
            check(lib.projcurve_curve_eval(ctx, branch, t, 0, out) == OK, "branch eval")
            gap = max(gap, distance_to_exact(list(out[:3]), t, 0.02))
        check(gap <= tol, "composed curve %g from the exact projection (eps_D %g)" % (gap, tol))
        print("  projection: %d points, %d pieces, %.3g from the exact curve"
              % (count.value, n_pieces.value, gap))

    # Bad arrays and a bad index: each status and its message.
    dummy = ctypes.c_void_p()
    bad_calls = [
        (lambda: lib.projcurve_curve_create_nurbs(ctx, 2, 3, doubles([0.0] * 9), None,
                                                  doubles([0, 0, 1, 0.5, 1, 1]),
                                                  ctypes.byref(dummy)), ERR_BAD_KNOTS),
        (lambda: lib.projcurve_curve_create_nurbs(ctx, 2, 3, doubles([0.0] * 9),
                                                  doubles([1.0, 0.0, 1.0]), knots,
                                                  ctypes.byref(dummy)), ERR_BAD_WEIGHT),
        (lambda: lib.projcurve_surface_create_nurbs(ctx, 2, 2, 3, 3,
                                                    doubles(ctrl[:4] + [math.inf] + ctrl[5:]),
                                                    None, knots, knots, ctypes.byref(dummy)),
         ERR_NOT_FINITE),
        (lambda: lib.projcurve_curve_create_nurbs(ctx, 2, 2, doubles([0.0] * 6), None, knots,
                                                  ctypes.byref(dummy)), ERR_BAD_COUNT),
        (lambda: lib.projcurve_result_branch_info(ctx, result, 7, None, None, None, None, None),
         ERR_INDEX),
    ]
    for call, expected in bad_calls:
        lib.projcurve_context_clear(ctx)
        status = call()
        text = message(lib, ctx)
        print("  %-20s %s" % (lib.projcurve_status_string(status).decode() + ":", text))
        check(status == expected, "status %d, expected %d (%s)" % (status, expected, text))
        check(lib.projcurve_context_status(ctx) == status, "context status after bad call")
        check(len(text) > 10, "message %r says what was wrong" % text)
        check(dummy.value is None, "no handle made by a refused call")

    lib.projcurve_curve_destroy(branch)
    lib.projcurve_result_destroy(result)
    lib.projcurve_curve_destroy(curve)
    lib.projcurve_surface_destroy(surface)


def installed_library(cmake, build_dir, prefix):
    subprocess.run([cmake, "--install", build_dir, "--prefix", prefix], check=True,
                   stdout=subprocess.DEVNULL)
    found = glob.glob(os.path.join(prefix, "lib*", "**", "libprojcurve.so.1"), recursive=True)
    if not found:
        sys.exit("FAIL: libprojcurve.so.1 not installed under %s" % prefix)
    return found[0]


def main(argv):
    if len(argv) == 2:
        run(argv[1])
    elif len(argv) == 4 and argv[1] == "--install":
        with tempfile.TemporaryDirectory(prefix="projcurve-ctypes-") as prefix:
            lib_path = installed_library(argv[2], argv[3], prefix)
            print("loading", lib_path)
            run(lib_path)
    else:
        sys.exit(__doc__)
    print("test_ctypes: %s" % ("OK" if failures == 0 else "%d failures" % failures))
    return 0 if failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
