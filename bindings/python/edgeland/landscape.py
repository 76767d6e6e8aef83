"""The landscape: a world of integer polygons of materials 0..255, edited and queried."""
import ctypes

from . import _native, results
from ._handles import Handle, Owned, made
from .errors import call
from .shapes import Shape, _box, _point, as_shape

_lib = _native.lib

_TREES = {"quadtree": 0, "kd": 1}


def _config(tree="quadtree", edge_cap=None, merge_below=None, min_cell_size=None,
            grid_depth=None, checked=False, max_vertices=None, max_shape_vertices=None,
            max_cells=None):
    c = _native.LandscapeConfig()
    _lib.el_landscape_config_init(ctypes.byref(c))
    c.tree = _TREES[tree]
    for name, value in (("edge_cap", edge_cap), ("merge_below", merge_below),
                        ("min_cell_size", min_cell_size), ("grid_depth", grid_depth),
                        ("max_vertices", max_vertices), ("max_shape_vertices", max_shape_vertices),
                        ("max_cells", max_cells)):
        if value is not None:
            setattr(c, name, value)
    c.flags = 1 if checked else 0
    return c


class Landscape(Handle):
    """A changeable world (C++ edgeland::Landscape).

    Landscape(((0, 0), (1024, 512)), fill=1) is a world box filled with material 1. Edits take a
    Shape (or polygons) and return a ChangeSet; a failed edit raises its EdgelandError and leaves
    the world exactly as it was. copy() is an O(1) snapshot. Keyword arguments: tree ("quadtree"
    or "kd"), edge_cap, merge_below, min_cell_size, grid_depth, checked, max_vertices,
    max_shape_vertices, max_cells (spatial/include/edgeland/spatial/types.hpp).
    """

    _destroy = "el_landscape_destroy"

    def __init__(self, world=None, fill=0, *, _pointer=None, **config):
        if _pointer is None:
            c = _config(**config)
            _pointer = made(_lib.el_landscape_create, ctypes.byref(_box(world)), fill,
                            ctypes.byref(c))
        super().__init__(_pointer)

    # --- snapshots and saves -------------------------------------------------------------
    def copy(self):
        """A snapshot in O(1): later edits of either never show in the other."""
        return Landscape(_pointer=made(_lib.el_landscape_clone, self))

    __copy__ = copy

    def save(self):
        """The versioned, checksummed binary save, as bytes."""
        with Owned(made(_lib.el_landscape_save, self), "el_bytes_destroy") as h:
            return results.read_bytes(h)

    @classmethod
    def load(cls, data, **limits):
        """A world from save bytes (untrusted: LoadError names the byte offset). Keyword
        arguments: max_vertices, max_shape_vertices, max_cells."""
        c = _config(**limits)
        buffer = (ctypes.c_uint8 * len(data)).from_buffer_copy(data)
        return cls(_pointer=made(_lib.el_landscape_load, buffer, len(data), ctypes.byref(c)))

    # --- edits ----------------------------------------------------------------------------
    def _edit(self, function, shape, *args):
        shape = as_shape(shape)
        return results.change_set(Owned(made(function, self, shape, *args),
                                            "el_changes_destroy"))

    def carve(self, shape):
        """Everything under the shape becomes empty space (material 0)."""
        return self._edit(_lib.el_landscape_carve, shape)

    def fill(self, shape, material):
        """Everything under the shape becomes `material`."""
        return self._edit(_lib.el_landscape_fill, shape, material)

    def fill_empty(self, shape, material):
        """Only the empty space under the shape becomes `material`."""
        return self._edit(_lib.el_landscape_fill_empty, shape, material)

    def replace(self, shape, from_material, to_material):
        """Only `from_material` under the shape becomes `to_material`."""
        return self._edit(_lib.el_landscape_replace, shape, from_material, to_material)

    def relabel(self, shape, mapping):
        """Under the shape every material m in `mapping` becomes mapping[m], all at once."""
        pairs = [v for item in mapping.items() for v in item]
        array = (ctypes.c_int32 * len(pairs))(*pairs)
        return self._edit(_lib.el_landscape_relabel, shape, array, len(mapping))

    # --- queries --------------------------------------------------------------------------
    def material_at(self, p):
        """The material at p (half-open: a point on a boundary has the material east of it)."""
        m = ctypes.c_uint8()
        call(_lib.el_landscape_material_at, self, ctypes.byref(_point(p)), ctypes.byref(m))
        return m.value

    def crossings(self, a, b):
        """Every material change along the segment a -> b, in order, exact."""
        with Owned(made(_lib.el_landscape_crossings, self, ctypes.byref(_point(a)),
                            ctypes.byref(_point(b))), "el_crossings_destroy") as h:
            count = ctypes.c_size_t()
            data = _lib.el_crossings_data(h, ctypes.byref(count))
            return [results.crossing(data[i]) for i in range(count.value)]

    def raycast(self, a, b):
        """The first entry into a solid material other than the one at a, or None."""
        hit, c = ctypes.c_int32(), _native.Crossing()
        call(_lib.el_landscape_raycast, self, ctypes.byref(_point(a)), ctypes.byref(_point(b)),
             ctypes.byref(hit), ctypes.byref(c))
        return results.crossing(c) if hit.value else None

    def overlaps(self, region):
        """The solid materials whose interiors meet the region's: a box ((x0, y0), (x1, y1)),
        a Shape or polygons. Ascending."""
        materials, count = (ctypes.c_uint8 * 256)(), ctypes.c_size_t()
        if isinstance(region, tuple) and len(region) == 2 and len(region[0]) == 2 \
                and isinstance(region[0][0], int):
            call(_lib.el_landscape_overlaps_box, self, ctypes.byref(_box(region)), materials,
                 ctypes.byref(count))
        else:
            call(_lib.el_landscape_overlaps_shape, self, as_shape(region), materials,
                 ctypes.byref(count))
        return list(materials[:count.value])

    def _polygons_handle(self, box):
        return Owned(made(_lib.el_landscape_polygons_in, self,
                              ctypes.byref(_box(box or self.world))), "el_polygons_destroy")

    def polygons_in(self, box=None):
        """The polygons whose bounding box meets the box (default: the world)."""
        with self._polygons_handle(box) as h:
            return results.polygons(h)

    def polygon_arrays(self, box=None):
        """polygons_in as numpy arrays (needs numpy): ids, materials, offsets, points."""
        with self._polygons_handle(box) as h:
            return results.polygon_arrays(h)

    def cells_in(self, box=None):
        """The boxes of the cells (the tree's leaves, empty ones too) that meet the closed box
        (default: the world), in tree order, each ((x0, y0), (x1, y1))."""
        cap = self.stats["cells"]  # every cell of the world: enough for any box
        cells, needed = (_native.Box * cap)(), ctypes.c_size_t()
        call(_lib.el_landscape_cells_in, self, ctypes.byref(_box(box or self.world)), cells, cap,
             ctypes.byref(needed))
        return [results.box_tuple(b) for b in cells[:needed.value]]

    def twice_area(self, material):
        """Twice the area of a material, exact (an int; it may pass 2^64)."""
        v = _native.Int128()
        call(_lib.el_landscape_twice_area, self, material, ctypes.byref(v))
        return v.value()

    @property
    def world(self):
        b = _native.Box()
        call(_lib.el_landscape_world, self, ctypes.byref(b))
        return results.box_tuple(b)

    @property
    def stats(self):
        s = _native.Stats()
        _lib.el_stats_init(ctypes.byref(s))
        call(_lib.el_landscape_stats, self, ctypes.byref(s))
        return {"polygons": s.polygons, "vertices": s.vertices, "cells": s.cells,
                "depth": s.depth, "bytes": s.bytes}

    @property
    def state_hash(self):
        """The 64-bit state hash: equal states, equal hashes, on every platform."""
        h = ctypes.c_uint64()
        call(_lib.el_landscape_state_hash, self, ctypes.byref(h))
        return h.value

    def check(self):
        """Every invariant over the whole world: the problems found (empty: valid)."""
        with Owned(made(_lib.el_landscape_check, self), "el_bytes_destroy") as h:
            return results.read_bytes(h).decode().splitlines()

    def set_checked(self, on=True):
        """Checked mode: every edit re-verifies every invariant (tests, tools)."""
        call(_lib.el_landscape_set_checked, self, 1 if on else 0)

    def start_log(self):
        call(_lib.el_landscape_start_log, self)

    def stop_log(self):
        call(_lib.el_landscape_stop_log, self)

    @property
    def log(self):
        """The edit log recorded since start_log() (README.md, "Landscape edit logs")."""
        with Owned(made(_lib.el_landscape_log, self), "el_bytes_destroy") as h:
            return results.read_bytes(h).decode()
