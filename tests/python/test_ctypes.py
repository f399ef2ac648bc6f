#!/usr/bin/env python3
"""Drive the installed libprojcurve.so through ctypes, as an FFI user would.

Usage:
    test_ctypes.py LIBRARY                 # a path to libprojcurve.so.1
    test_ctypes.py --install CMAKE BUILD   # install BUILD into a temporary
                                           # prefix first and use that library

Only the standard library is used. The declarations below mirror
include/projcurve.h; the test checks the values an FFI binding depends on
(status codes, version, option bounds) and reads the context message after
each bad call.
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
ERR_VERSION = 14
ERR_WRONG_KIND = 23

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
          and default.value == 1e7, "MAX_POINTS info %r" % ((kind.value, lo.value, hi.value, default.value),))

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

    lib.projcurve_options_destroy(opts)
    lib.projcurve_context_destroy(ctx)
    lib.projcurve_context_destroy(None)


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
