# SPDX-License-Identifier: BSD-3-Clause
"""projcurve.Error and one subclass per failure status of the header,
made from the generated enum (ZeroDirectionError for
PROJCURVE_ERR_ZERO_DIRECTION, ...)."""
import enum

from . import _generated as gen

Status = enum.IntEnum("Status", {k[len("PROJCURVE_"):]: v
                                 for k, v in gen.ENUMS["projcurve_status"].items()})


class Error(Exception):
    """A failed call: .status (a Status), .message (the library's message
    from the call's context, or the package's for input it refused before
    calling), .function (the C function, or the package's)."""

    def __init__(self, status, message, function=None):
        self.status = Status(status) if status in Status._value2member_map_ else status
        self.message = message
        self.function = function
        super().__init__(status, message, function)

    def __str__(self):
        name = self.status.name if isinstance(self.status, Status) else str(self.status)
        where = " in %s" % self.function if self.function else ""
        return "%s (%s%s)" % (self.message, name, where)


def _class_name(status_name):
    return "".join(w.capitalize() for w in status_name[len("ERR_"):].split("_")) + "Error"


ERROR_CLASSES = {}
for _s in Status:
    if _s.name.startswith("ERR_"):
        ERROR_CLASSES[_s.value] = type(_class_name(_s.name), (Error,),
                                       {"__doc__": "Status %s." % _s.name,
                                        "__module__": "projcurve"})


def error_for(status, message, function=None):
    return ERROR_CLASSES.get(status, Error)(status, message, function)


def fail(status_name, message, function=None):
    """The exception for input the package refuses itself (same classes)."""
    return error_for(Status["ERR_" + status_name].value, message, function)
