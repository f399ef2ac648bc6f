# SPDX-License-Identifier: BSD-3-Clause
"""Ownership of C handles.

A _Resource holds one C pointer and the function that destroys it (none
for a borrowed pointer, e.g. a model's surface) and strong references to
the resources it depends on (the model a borrowed surface lives in, the
surface a face was made on). Resources reference only resources, never
wrapper objects, so they form no cycles: reference counting always
releases a dependent before what it depends on, even when the Python
objects around them sit in a garbage cycle. Handle.close() (and a with
block) releases early: first the handles that depend on it, then itself;
later use raises NullArgumentError naming the closed handle."""
import weakref

from ._errors import fail


class _Resource:
    __slots__ = ("ptr", "destroy", "parents", "dependents", "__weakref__")

    def __init__(self, ptr, destroy, parents):
        self.ptr, self.destroy, self.parents = ptr, destroy, parents
        # weak: what depends on this one, closed first by close(); held on
        # the resources (not the wrappers), so that a dependent is reached
        # through a parent whose wrapper is gone (a model's shape's faces)
        self.dependents = weakref.WeakSet()
        for p in parents:
            p.dependents.add(self)

    def release(self):
        ptr, destroy = self.ptr, self.destroy
        self.ptr, self.destroy, self.parents = None, None, ()
        if ptr is not None and destroy is not None:
            destroy(ptr)

    def close(self):
        """Releases the dependents, then this. The depth is that of the
        ownership chains (model, shape, face, surface: at most four)."""
        if self.ptr is None:
            return
        for d in list(self.dependents):
            d.close()
        self.release()

    def __del__(self):
        try:
            self.release()
        except Exception:  # interpreter shutdown: nothing left to report to
            pass


class Handle:
    """Base of every object that holds a C handle."""
    _kind = "handle"

    def __init__(self, ptr, destroy=None, parents=()):
        """ptr: the C pointer (int); destroy: the C function that releases
        it, None when borrowed; parents: Handles that must outlive it."""
        self._res = _Resource(ptr, destroy, tuple(p._res for p in parents))

    @property
    def _ptr(self):
        ptr = self._res.ptr
        if ptr is None:
            raise fail("NULL_ARGUMENT", "this %s is closed" % self._kind, "projcurve")
        return ptr

    @property
    def closed(self):
        return self._res.ptr is None

    def close(self):
        """Releases the C handle now (and every handle that depends on it).
        Closing twice does nothing."""
        self._res.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False
