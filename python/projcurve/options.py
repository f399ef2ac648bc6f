# SPDX-License-Identifier: BSD-3-Clause
"""Projection options, table-driven: the option names come from the
header's projcurve_option enum (generated), their types, bounds and
defaults from the library's projcurve_option_info."""
import collections
import ctypes
import enum

from . import _generated as gen
from ._errors import fail
from ._handle import Handle
from ._lib import CALLBACK_TYPES, call, fn

Option = enum.IntEnum("Option", {k[len("PROJCURVE_OPT_"):]: v
                                 for k, v in gen.ENUMS["projcurve_option"].items()})
OptionType = enum.IntEnum("OptionType", {k[len("PROJCURVE_OPTION_"):]: v
                                         for k, v in gen.ENUMS["projcurve_option_type"].items()})

OptionInfo = collections.namedtuple("OptionInfo", "name key type min max default")

_TABLE = None


def option_table():
    """{name: OptionInfo} of every option the loaded library knows, names
    in lower case ("tol_distance", ...)."""
    global _TABLE  # a cache of immutable facts about the loaded library
    if _TABLE is None:
        table = {}
        for opt in Option:
            t, lo, hi, de = ctypes.c_int(), ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
            status = fn["projcurve_option_info"](None, opt.value, ctypes.byref(t),
                                                 ctypes.byref(lo), ctypes.byref(hi),
                                                 ctypes.byref(de))
            if status != 0:
                continue  # an option of a newer header than the library
            kind = OptionType(t.value)
            conv = float if kind == OptionType.DOUBLE else int
            table[opt.name.lower()] = OptionInfo(opt.name.lower(), opt, kind, conv(lo.value),
                                                 conv(hi.value), conv(de.value))
        _TABLE = table
    return _TABLE


class Options(Handle):
    """Options of a projection call: Options(tol_distance=1e-6, method=1),
    then opts.tol_angle_deg = 0.5, opts["max_points"], opts.get(name),
    opts.set(name, value), dict(opts.items()). opts.progress = f sets a
    progress function f(fraction_done) -> stop (truthy stops the call, which
    then raises CancelledError; an exception raised in f stops it and is
    raised again after the call)."""
    _kind = "options"

    def __init__(self, **values):
        out = ctypes.c_void_p()
        call("projcurve_options_create", ctypes.byref(out))
        object.__setattr__(self, "_progress", None)
        object.__setattr__(self, "_progress_cb", None)
        object.__setattr__(self, "progress_error", None)
        super().__init__(out.value, fn["projcurve_options_destroy"])
        for name, value in values.items():
            self.set(name, value)

    @staticmethod
    def info(name):
        """OptionInfo(name, key, type, min, max, default) of one option."""
        table = option_table()
        if name not in table:
            raise fail("UNKNOWN_OPTION", "no option %r (options: %s)"
                       % (name, ", ".join(sorted(table))), "projcurve")
        return table[name]

    @staticmethod
    def names():
        return list(option_table())

    def set(self, name, value):
        info = self.info(name)
        if info.type == OptionType.DOUBLE:
            try:
                value = float(value)
            except (TypeError, ValueError):
                raise fail("INVALID_ARGUMENT", "option %s takes a number, not %r"
                           % (name, value), "projcurve") from None
            call("projcurve_options_set_double", self._ptr, info.key.value, value)
        else:
            if isinstance(value, float) and value.is_integer():
                value = int(value)
            if not isinstance(value, int):  # bool is an int: True is 1
                raise fail("INVALID_ARGUMENT", "option %s takes an integer, not %r"
                           % (name, value), "projcurve")
            if not -2 ** 63 <= value < 2 ** 63:  # a C long long
                raise fail("OUT_OF_RANGE", "option %s: %d is outside [%d, %d]"
                           % (name, value, info.min, info.max), "projcurve")
            call("projcurve_options_set_int", self._ptr, info.key.value, int(value))

    def get(self, name):
        info = self.info(name)
        if info.type == OptionType.DOUBLE:
            out = ctypes.c_double()
            call("projcurve_options_get_double", self._ptr, info.key.value, ctypes.byref(out))
        else:
            out = ctypes.c_longlong()
            call("projcurve_options_get_int", self._ptr, info.key.value, ctypes.byref(out))
        return out.value

    def items(self):
        return [(name, self.get(name)) for name in option_table()]

    def __getitem__(self, name):
        return self.get(name)

    def __setitem__(self, name, value):
        self.set(name, value)

    def __getattr__(self, name):
        if name.startswith("_") or name not in option_table():
            raise AttributeError(name)
        return self.get(name)

    def __setattr__(self, name, value):
        if name in option_table():
            self.set(name, value)
        elif name == "progress":
            self._set_progress(value)
        elif name.startswith("_") or name == "progress_error":
            object.__setattr__(self, name, value)
        else:
            raise fail("UNKNOWN_OPTION", "no option %r (options: %s)"
                       % (name, ", ".join(sorted(option_table()))), "projcurve")

    @property
    def progress(self):
        return self._progress

    def _set_progress(self, function):
        if function is None:
            null = CALLBACK_TYPES["projcurve_progress_fn"]()  # a NULL function pointer
            call("projcurve_options_set_progress", self._ptr, null, None)
            object.__setattr__(self, "_progress", None)
            object.__setattr__(self, "_progress_cb", None)
            return

        def trampoline(_user, fraction):
            try:
                return 1 if function(fraction) else 0
            except BaseException as e:  # raised again by the projection call
                object.__setattr__(self, "progress_error", e)
                return 1
        cb = CALLBACK_TYPES["projcurve_progress_fn"](trampoline)
        call("projcurve_options_set_progress", self._ptr, cb, None)
        object.__setattr__(self, "_progress", function)
        object.__setattr__(self, "_progress_cb", cb)  # alive as long as the options


__all__ = ["Options", "Option", "OptionType", "OptionInfo", "option_table"]
