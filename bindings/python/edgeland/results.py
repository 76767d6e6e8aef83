"""Results as Python values: polygons, change sets, crossings."""
import ctypes
from fractions import Fraction
from typing import NamedTuple

from . import _native

_lib = _native.lib


def box_tuple(b):
    return ((b.min.x, b.min.y), (b.max.x, b.max.y))


class Polygon(NamedTuple):
    """A landscape polygon: its id, material, the box of its cell, its points (CCW)."""
    id: int
    material: int
    cell: tuple
    points: list


class Crossing(NamedTuple):
    """A material change along a segment (C++ MaterialCrossing), exact: the parameter t along
    the segment and the point as Fractions, its rounding, the polygon entered (after != 0) or
    left and its edge, the edge's outward normal (not normalised)."""
    t: Fraction
    point: tuple
    rounded: tuple
    normal: tuple
    polygon: int
    edge: int
    before: int
    after: int


class ChangeSet:
    """What an edit changed: ids removed (ascending), polygons added (ascending id), the cells
    rebuilt, twice the change of area per material (exact; the values sum to 0). It keeps the C
    change set, which the game layer's trackers and mesh_update take."""

    def __init__(self, handle, removed, added, cells, area_delta):
        self._handle = handle
        self.removed, self.added, self.cells, self.area_delta = removed, added, cells, area_delta

    def __repr__(self):
        return "ChangeSet(removed=%d ids, added=%d polygons, cells=%d)" % (
            len(self.removed), len(self.added), len(self.cells))


def crossing(c):
    x = Fraction(c.x_num.value(), c.den.value())
    y = Fraction(c.y_num.value(), c.den.value())
    return Crossing(Fraction(c.t_num.value(), c.t_den.value()), (x, y),
                    (c.rounded.x, c.rounded.y), (c.normal.x, c.normal.y), c.polygon, c.edge,
                    c.before, c.after)


def polygons(handle):
    """The polygons of an el_polygons handle (read, not freed)."""
    count = ctypes.c_size_t()
    n = _lib.el_polygons_count(handle)
    ids = _lib.el_polygons_ids(handle, ctypes.byref(count))
    materials = _lib.el_polygons_materials(handle, ctypes.byref(count))
    cells = _lib.el_polygons_cells(handle, ctypes.byref(count))
    offsets = _lib.el_polygons_offsets(handle, ctypes.byref(count))
    points = _lib.el_polygons_points(handle, ctypes.byref(count))
    out = []
    for i in range(n):
        ring = [(points[k].x, points[k].y) for k in range(offsets[i], offsets[i + 1])]
        out.append(Polygon(ids[i], materials[i], box_tuple(cells[i]), ring))
    return out


def polygon_arrays(handle):
    """The arrays of an el_polygons handle as numpy arrays (copies): ids, materials, offsets,
    points (an (n, 2) int64 array)."""
    import numpy
    count = ctypes.c_size_t()
    n = _lib.el_polygons_count(handle)

    def grab(function, ctype, size=None):
        pointer = function(handle, ctypes.byref(count))
        if not count.value:
            return numpy.zeros(0, dtype=numpy.dtype(ctype))
        return numpy.ctypeslib.as_array(ctypes.cast(pointer, ctypes.POINTER(ctype)),
                                        shape=(size or count.value,)).copy()

    ids = grab(_lib.el_polygons_ids, ctypes.c_uint64)
    materials = grab(_lib.el_polygons_materials, ctypes.c_uint8)
    offsets = grab(_lib.el_polygons_offsets, ctypes.c_uint32)
    _lib.el_polygons_points(handle, ctypes.byref(count))
    points = grab(_lib.el_polygons_points, ctypes.c_int64, 2 * count.value).reshape(-1, 2)
    assert len(ids) == n
    return ids, materials, offsets, points


def change_set(handle):
    """The Python ChangeSet of an el_changes handle (a Handle it keeps, or a borrowed pointer
    whose owner it must outlive)."""
    count = ctypes.c_size_t()
    removed = _native.array(_lib.el_changes_removed(handle, ctypes.byref(count)), count.value)
    added = polygons(_lib.el_changes_added(handle))
    cells = [box_tuple(b) for b in
             _native.array(_lib.el_changes_cells(handle, ctypes.byref(count)), count.value)]
    deltas = _native.array(_lib.el_changes_area_delta(handle, ctypes.byref(count)), count.value)
    return ChangeSet(handle, removed, added, cells,
                     {d.material: d.twice_area.value() for d in deltas})


def read_bytes(handle):
    size = ctypes.c_size_t()
    data = _lib.el_bytes_data(handle, ctypes.byref(size))
    return ctypes.string_at(data, size.value) if size.value else b""
