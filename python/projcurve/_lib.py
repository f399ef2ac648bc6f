# SPDX-License-Identifier: BSD-3-Clause
"""Finding libprojcurve, declaring its functions from the generated table,
and calling them with a context whose message becomes the exception."""
import ctypes
import os
import sys
import sysconfig

from . import _generated as gen
from ._errors import error_for

MAJOR = int(gen.VERSION.split(".")[0])

if sys.platform == "darwin":
    SONAME = "libprojcurve.%d.dylib" % MAJOR
elif sys.platform == "win32":
    SONAME = "projcurve.dll"
else:
    SONAME = "libprojcurve.so.%d" % MAJOR

def _candidates():
    """Paths to try, in order; PROJCURVE_LIBRARY, when set, is the only one."""
    env = os.environ.get("PROJCURVE_LIBRARY")
    if env:
        return [env]
    here = os.path.dirname(os.path.abspath(__file__))
    found = [os.path.join(here, SONAME)]  # bundled next to the package
    try:  # installed by cmake --install: the library of the same prefix
        from ._install_location import LIBDIR
        found.append(os.path.normpath(os.path.join(here, LIBDIR, SONAME)))
    except ImportError:
        pass
    # the prefix of the running python (a venv, /usr/local ...)
    libdirs = ["lib", "lib64"]
    multiarch = sysconfig.get_config_var("MULTIARCH")
    if multiarch:
        libdirs.append(os.path.join("lib", multiarch))
    for prefix in dict.fromkeys((sys.prefix, sys.base_prefix)):
        found += [os.path.join(prefix, sub, SONAME) for sub in libdirs]
    found.append(SONAME)  # the dynamic loader's own search (LD_LIBRARY_PATH, ld.so.cache)
    return found


_CTYPES = {
    "void": None, "int": ctypes.c_int, "uint": ctypes.c_uint, "size_t": ctypes.c_size_t,
    "double": ctypes.c_double, "float": ctypes.c_float, "long": ctypes.c_long,
    "ulong": ctypes.c_ulong, "longlong": ctypes.c_longlong, "ulonglong": ctypes.c_ulonglong,
    "uchar": ctypes.c_ubyte, "int32": ctypes.c_int32, "uint32": ctypes.c_uint32,
    "int64": ctypes.c_int64, "uint64": ctypes.c_uint64, "ptrdiff": ctypes.c_ssize_t,
    "handle": ctypes.c_void_p, "string": ctypes.c_char_p,
}

CALLBACK_TYPES = {}


def ctype_of(code):
    """A type code of _generated.py -> its ctypes type."""
    stars = len(code) - len(code.rstrip("*"))
    base = code.rstrip("*")
    if base.startswith("fn:"):
        t = CALLBACK_TYPES[base[3:]]
    elif base == "char" and stars:
        t, stars = ctypes.c_char_p, stars - 1
    else:
        t = _CTYPES[base]
    for _ in range(stars):
        t = ctypes.POINTER(t)
    return t


for _name, (_ret, _params) in gen.CALLBACKS.items():
    CALLBACK_TYPES[_name] = ctypes.CFUNCTYPE(ctype_of(_ret), *(ctype_of(p) for p in _params))


def _missing(name):
    def fail(*_args):
        raise error_for(gen.ENUMS["projcurve_status"]["PROJCURVE_ERR_UNSUPPORTED"],
                        "the loaded library %s has no function %s (older than the package)"
                        % (path, name), name)
    return fail


def _load():
    tried = []
    for candidate in _candidates():
        if os.sep in candidate and not os.path.exists(candidate):
            tried.append(candidate)
            continue
        try:
            return ctypes.CDLL(candidate), candidate
        except OSError as e:
            tried.append("%s (%s)" % (candidate, e))
    raise ImportError("projcurve: libprojcurve not found; set PROJCURVE_LIBRARY to its path. "
                      "Tried: " + "; ".join(tried))


lib, path = _load()

# Every function of the header, declared from the generated table.
fn = {}
for _name, (_ret, _params) in gen.FUNCTIONS.items():
    try:
        f = getattr(lib, _name)
    except AttributeError:
        fn[_name] = _missing(_name)
        continue
    f.restype = ctype_of(_ret)
    f.argtypes = [ctype_of(code) for _, code in _params]
    fn[_name] = f

_loaded = fn["projcurve_version_number"]()
if _loaded // 10000 != MAJOR:
    raise ImportError("projcurve: %s is version %d.%d.%d, the package needs major version %d"
                      % (path, _loaded // 10000, _loaded // 100 % 100, _loaded % 100, MAJOR))

OK = gen.ENUMS["projcurve_status"]["PROJCURVE_OK"]


class Context:
    """One projcurve_context for the length of a call (contexts are not
    shared between threads; one per call needs no lock). limits: {limit
    enum value: value} set on it first (projcurve_context_set_limit)."""
    __slots__ = ("ptr", "limits")

    def __init__(self, limits=None):
        self.limits = limits or {}

    def __enter__(self):
        ptr = ctypes.c_void_p()
        status = fn["projcurve_context_create"](MAJOR, ctypes.byref(ptr))
        if status != OK:
            raise error_for(status, fn["projcurve_status_string"](status).decode(),
                            "projcurve_context_create")
        self.ptr = ptr
        try:
            for limit, value in self.limits.items():
                self.check(fn["projcurve_context_set_limit"](ptr, limit, value),
                           "projcurve_context_set_limit")
        except BaseException:
            fn["projcurve_context_destroy"](ptr)
            raise
        return self

    def __exit__(self, *exc):
        fn["projcurve_context_destroy"](self.ptr)
        return False

    def message(self):
        return fn["projcurve_context_message"](self.ptr).decode("utf-8", "replace")

    def check(self, status, name):
        if status != OK:
            raise error_for(status, self.message(), name)


def call(name, *args, limits=None):
    """Calls a function that takes a context first; raises on failure."""
    with Context(limits) as ctx:
        ctx.check(fn[name](ctx.ptr, *args), name)


LIMIT_CONTROL_POINTS = gen.ENUMS["projcurve_limit"]["PROJCURVE_LIMIT_CONTROL_POINTS"]


def limits(max_control_points):
    """The context limits of a creation call (None: the library's default)."""
    if max_control_points is None:
        return None
    if not isinstance(max_control_points, int) or not 0 <= max_control_points < 2 ** 64:
        raise error_for(gen.ENUMS["projcurve_status"]["PROJCURVE_ERR_OUT_OF_RANGE"],
                        "max_control_points: %r is not a size" % (max_control_points,),
                        "projcurve")
    return {LIMIT_CONTROL_POINTS: max_control_points}


def call_fast(name, *args):
    """The same without a context (for calls in loops); a failure is
    repeated with one to read its message."""
    status = fn[name](None, *args)
    if status != OK:
        call(name, *args)
        raise error_for(status, fn["projcurve_status_string"](status).decode(), name)
