"""Ownership of C handles: each Python object owns one and frees it once."""
import ctypes

from . import _native


class Handle:
    """Owns one C handle; close() (or garbage collection, or `with`) frees it."""

    _destroy = None  # the el_*_destroy function's name
    _pointer = None  # until the constructor succeeds

    def __init__(self, pointer):
        self._pointer = ctypes.c_void_p(pointer)

    @property
    def _as_parameter_(self):
        return self._pointer

    def close(self):
        if self._pointer is not None and self._pointer.value:
            getattr(_native.lib, self._destroy)(self._pointer)
            self._pointer = ctypes.c_void_p()

    def __del__(self):
        if _native is not None and getattr(_native, "lib", None) is not None:
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def made(function, *args):
    """Calls an el_* function returning a new handle through its out-parameter."""
    from .errors import call
    out = ctypes.c_void_p()
    call(function, *args, ctypes.byref(out))
    return out.value


class Owned(Handle):
    """A result handle, freed with its Python owner (or at the end of a with block)."""

    def __init__(self, pointer, destroy):
        self._destroy = destroy
        super().__init__(pointer)
