"""edgeland's errors as Python exceptions, one class per el_status (the C++ class in brackets).

Every exception is an EdgelandError carrying the fields of the C API's el_error: `status`,
`kind` (the rule, setting or limit), `operand`, `index`, `vertex`, `value`, `limit`, `minimum`,
`where` and the message. A failed edit leaves the landscape exactly as it was.
"""
import ctypes

from . import _native

NONE = (1 << 64) - 1  # EL_NONE: no index

RULES = ("too-few-vertices", "coordinate-out-of-range", "repeated-vertex", "self-intersection",
         "spike", "not-counter-clockwise", "overlapping-interiors", "inverted-box")
SETTINGS = ("world-out-of-range", "world-empty", "edge-cap", "merge-below", "min-cell-size",
            "grid-depth", "tree", "grid-depth-beyond-cells")
LIMITS = ("vertices", "shape-vertices", "cells", "polygon-ids")


class EdgelandError(Exception):
    """Base of every edgeland error."""

    def __init__(self, status, detail):
        super().__init__(detail.message.decode("utf-8", "replace"))
        self.status = status
        self.kind = detail.kind
        self.operand = detail.operand
        self.index = None if detail.index == NONE else detail.index
        self.vertex = None if detail.vertex == NONE else detail.vertex
        self.value = detail.value
        self.limit = detail.limit
        self.minimum = detail.minimum
        self.where = (detail.where.x, detail.where.y)


class NullArgument(EdgelandError, ValueError):
    """EL_NULL_ARGUMENT: a required handle was missing (a closed object used)."""


class OutOfMemory(EdgelandError, MemoryError):
    """EL_OUT_OF_MEMORY [std::bad_alloc]."""


class VersionMismatch(EdgelandError):
    """EL_VERSION_MISMATCH: the library does not serve this package's version."""


class InternalError(EdgelandError):
    """EL_INTERNAL: a bug in edgeland [LandscapeInternalError, InternalError]."""


class InvalidInput(EdgelandError, ValueError):
    """EL_INVALID_INPUT: a shape breaks a rule of validate(); `rule` names it [InvalidInput]."""

    @property
    def rule(self):
        return RULES[self.kind] if self.kind < len(RULES) else str(self.kind)


class CoordinateOutOfRange(InvalidInput):
    """EL_COORDINATE_OUT_OF_RANGE: beyond |c| <= 2^31 - 1 [CoordinateOutOfRange]."""


class InvalidBox(InvalidInput):
    """EL_INVALID_BOX [InvalidBox]."""


class TooManyVertices(EdgelandError, ValueError):
    """EL_TOO_MANY_VERTICES [TooManyVertices]."""


class InvalidArgument(EdgelandError, ValueError):
    """EL_INVALID_ARGUMENT: a number below its minimum [InvalidArgument]."""


class ArgumentOutOfRange(EdgelandError, ValueError):
    """EL_ARGUMENT_OUT_OF_RANGE [ArgumentOutOfRange]."""


class NonPositiveArea(EdgelandError, ValueError):
    """EL_NON_POSITIVE_AREA [NonPositiveArea]."""


class InvalidOverlay(EdgelandError, ValueError):
    """EL_INVALID_OVERLAY [InvalidOverlay]."""


class InvalidConfig(EdgelandError, ValueError):
    """EL_INVALID_CONFIG: the world box or the configuration; `setting` names it."""

    @property
    def setting(self):
        return SETTINGS[self.kind] if self.kind < len(SETTINGS) else str(self.kind)


class InvalidMaterial(EdgelandError, ValueError):
    """EL_INVALID_MATERIAL: a material number outside 0..255; `value` is the number."""


class LimitExceeded(EdgelandError):
    """EL_LIMIT_EXCEEDED: `limit_name` passed, `value` requested of at most `limit`."""

    @property
    def limit_name(self):
        return LIMITS[self.kind] if self.kind < len(LIMITS) else str(self.kind)


class LoadError(EdgelandError, ValueError):
    """EL_LOAD_ERROR: a save that cannot be read, `index` the byte offset [LoadError]; or the
    line (`index`, 1-based) an edit log's replay stopped at (replay_log)."""


class DeltaError(EdgelandError, ValueError):
    """EL_DELTA_ERROR: a delta that cannot be read or applied; `index` is the byte offset."""


class DeltaMismatch(EdgelandError):
    """EL_DELTA_MISMATCH: a delta of another world, version, base or result; `kind` says which."""


class InvalidPath(EdgelandError, ValueError):
    """EL_INVALID_PATH: a tree path that names no node; `index` is the path's length."""


class RegionNotLoaded(EdgelandError):
    """EL_REGION_NOT_LOADED: an edit or query reached an unloaded region; `index` is its path's
    length."""


class UnknownPolygon(EdgelandError, LookupError):
    """EL_UNKNOWN_POLYGON: a polygon id the landscape no longer holds; `index` is the id."""


class StaleIsland(EdgelandError):
    """EL_STALE_ISLAND: the island changed since it was found; `index` is the polygon id."""


class IndexOutOfRange(EdgelandError, IndexError):
    """EL_INDEX_OUT_OF_RANGE."""


class BufferTooSmall(EdgelandError):
    """EL_BUFFER_TOO_SMALL."""


BY_STATUS = {1: NullArgument, 2: OutOfMemory, 3: VersionMismatch, 4: InternalError,
             10: InvalidInput, 11: CoordinateOutOfRange, 12: InvalidBox, 13: TooManyVertices,
             14: InvalidArgument, 15: ArgumentOutOfRange, 16: NonPositiveArea,
             17: InvalidOverlay, 20: InvalidConfig, 21: InvalidMaterial, 22: LimitExceeded,
             23: LoadError, 24: DeltaError, 25: DeltaMismatch, 26: InvalidPath,
             27: RegionNotLoaded, 28: UnknownPolygon, 30: StaleIsland, 40: IndexOutOfRange,
             41: BufferTooSmall}


def failure(function, *args):
    """Calls an el_* function that takes an el_error* last: its exception, or None on success."""
    detail = _native.Error()
    _native.lib.el_error_init(ctypes.byref(detail))
    status = function(*args, ctypes.byref(detail))
    return None if status == 0 else BY_STATUS.get(status, EdgelandError)(status, detail)


def call(function, *args):
    """Calls an el_* function that takes an el_error* last; raises its exception on failure."""
    error = failure(function, *args)
    if error is not None:
        raise error
