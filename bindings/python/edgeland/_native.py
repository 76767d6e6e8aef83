"""The C API (capi/include/edgeland/edgeland.h) through ctypes: its structs and prototypes.

Nothing here is for users; the rest of the package wraps it. The library is found through
$EDGELAND_C_LIBRARY (a path to libedgeland_c.so / edgeland_c.dll / libedgeland_c.dylib), else
by the system's search (ctypes.util.find_library("edgeland_c")).
"""
import ctypes
import ctypes.util
import os

from ctypes import (POINTER, Structure, c_char, c_double, c_int32, c_int64, c_size_t, c_uint8,
                    c_uint32, c_uint64, c_void_p)

VERSION = (1 << 16) | (0 << 8) | 0  # the EL_VERSION this package was written for


class Point(Structure):
    _fields_ = [("x", c_int64), ("y", c_int64)]


class Box(Structure):
    _fields_ = [("min", Point), ("max", Point)]


class Int128(Structure):
    _fields_ = [("lo", c_uint64), ("hi", c_int64), ("approx", c_double)]

    def value(self):
        return (self.hi << 64) | self.lo


class Crossing(Structure):
    _fields_ = [("t_num", Int128), ("t_den", Int128), ("x_num", Int128), ("y_num", Int128),
                ("den", Int128), ("rounded", Point), ("normal", Point), ("polygon", c_uint64),
                ("edge", c_uint32), ("before", c_uint8), ("after", c_uint8),
                ("reserved", c_uint8 * 2)]


class AreaDelta(Structure):
    _fields_ = [("twice_area", Int128), ("material", c_uint32), ("reserved", c_uint32)]


class Error(Structure):
    _fields_ = [("struct_size", c_uint32), ("status", c_int32), ("kind", c_uint32),
                ("operand", c_uint32), ("index", c_uint64), ("vertex", c_uint64),
                ("value", c_int64), ("limit", c_int64), ("minimum", c_int64), ("where", Point),
                ("message", c_char * 256)]


class ChainInfo(Structure):
    _fields_ = [("cell", Box), ("ghost_prev", Point), ("ghost_next", Point), ("id", c_uint64),
                ("closed", c_uint32), ("reserved", c_uint32)]


class IslandInfo(Structure):
    _fields_ = [("bounds", Box), ("twice_area", Int128), ("first_piece", c_uint32),
                ("piece_count", c_uint32)]


class DetachedInfo(Structure):
    _fields_ = [("twice_area", Int128), ("centroid_x_num", Int128), ("centroid_y_num", Int128),
                ("centroid_den", Int128)]


class PhysicsMaterials(Structure):
    _fields_ = [("struct_size", c_uint32), ("flags", c_uint32), ("solid", c_uint8 * 256),
                ("anchored", c_uint8 * 256)]


class GameOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("flags", c_uint32), ("debris_budget", c_uint64),
                ("max_piece_vertices", c_uint32), ("max_debris_wait", c_uint32),
                ("solid", c_uint8 * 256), ("anchored", c_uint8 * 256)]


class DebrisInfo(Structure):
    _fields_ = [("bounds", Box), ("twice_area", Int128), ("centroid_x_num", Int128),
                ("centroid_y_num", Int128), ("centroid_den", Int128), ("first_region", c_uint32),
                ("region_count", c_uint32), ("first_piece", c_uint32), ("piece_count", c_uint32)]


class GameWork(Structure):
    _fields_ = [("struct_size", c_uint32), ("reserved", c_uint32), ("cells_scanned", c_uint64),
                ("boundary_passes", c_uint64), ("cells_traced", c_uint64),
                ("islands_found", c_uint64), ("islands_detached", c_uint64),
                ("debris_waiting", c_uint64)]


class LandscapeConfig(Structure):
    _fields_ = [("struct_size", c_uint32), ("tree", c_uint32), ("edge_cap", c_uint32),
                ("merge_below", c_uint32), ("min_cell_size", c_int64), ("grid_depth", c_int32),
                ("flags", c_uint32), ("max_vertices", c_uint64),
                ("max_shape_vertices", c_uint64), ("max_cells", c_uint64)]


class Stats(Structure):
    _fields_ = [("struct_size", c_uint32), ("reserved", c_uint32), ("polygons", c_uint64),
                ("vertices", c_uint64), ("cells", c_uint64), ("depth", c_uint64),
                ("bytes", c_uint64)]


# Layout checks against the header's own asserts (EL_LAYOUT_ASSERT).
assert ctypes.sizeof(Crossing) == 168 and Crossing.polygon.offset == 152
assert ctypes.sizeof(Error) == 328 and Error.message.offset == 72
assert ctypes.sizeof(LandscapeConfig) == 56 and ctypes.sizeof(Stats) == 48
assert ctypes.sizeof(AreaDelta) == 32 and ctypes.sizeof(Int128) == 24
assert ctypes.sizeof(ChainInfo) == 80 and ctypes.sizeof(IslandInfo) == 64
assert ctypes.sizeof(DetachedInfo) == 96 and ctypes.sizeof(PhysicsMaterials) == 520
assert ctypes.sizeof(GameOptions) == 536 and GameOptions.solid.offset == 24
assert ctypes.sizeof(DebrisInfo) == 144 and DebrisInfo.first_region.offset == 128
assert ctypes.sizeof(GameWork) == 56


def _load():
    path = os.environ.get("EDGELAND_C_LIBRARY") or ctypes.util.find_library("edgeland_c")
    if not path:
        raise ImportError("libedgeland_c not found: set EDGELAND_C_LIBRARY to its path "
                          "(bindings/python/README.md)")
    return ctypes.CDLL(path)


lib = _load()

_status = c_int32
_err = POINTER(Error)
_handle = c_void_p
_out = POINTER(c_void_p)
_count = POINTER(c_size_t)

# name: (restype, argtypes); every el_* function this package calls.
_PROTOTYPES = {
    "el_version": (c_uint32, []),
    "el_check_version": (c_int32, [c_uint32]),
    "el_status_name": (ctypes.c_char_p, [c_int32]),
    "el_error_init": (None, [_err]),
    "el_shape_create": (_status, [POINTER(c_int64), POINTER(c_uint32), c_size_t, _out, _err]),
    "el_shape_circle": (_status, [POINTER(Point), c_int64, _out, _err]),
    "el_shape_regular_polygon": (_status, [POINTER(Point), c_int64, c_int64, c_int64, c_int64,
                                           _out, _err]),
    "el_shape_capsule": (_status, [POINTER(Point), POINTER(Point), c_int64, _out, _err]),
    "el_shape_box": (_status, [POINTER(Box), _out, _err]),
    "el_shape_rotated_box": (_status, [POINTER(Point), c_int64, c_int64, c_int64, c_int64, _out,
                                       _err]),
    "el_shape_import": (_status, [POINTER(c_int64), POINTER(c_uint32), POINTER(c_uint32),
                                  c_size_t, _out, _err]),
    "el_shape_polygons": (_status, [_handle, _out, _err]),
    "el_shape_destroy": (None, [_handle]),
    "el_landscape_config_init": (None, [POINTER(LandscapeConfig)]),
    "el_landscape_create": (_status, [POINTER(Box), c_int32, POINTER(LandscapeConfig), _out,
                                      _err]),
    "el_landscape_clone": (_status, [_handle, _out, _err]),
    "el_landscape_destroy": (None, [_handle]),
    "el_landscape_carve": (_status, [_handle, _handle, _out, _err]),
    "el_landscape_fill": (_status, [_handle, _handle, c_int32, _out, _err]),
    "el_landscape_fill_empty": (_status, [_handle, _handle, c_int32, _out, _err]),
    "el_landscape_replace": (_status, [_handle, _handle, c_int32, c_int32, _out, _err]),
    "el_landscape_relabel": (_status, [_handle, _handle, POINTER(c_int32), c_size_t, _out,
                                       _err]),
    "el_landscape_material_at": (_status, [_handle, POINTER(Point), POINTER(c_uint8), _err]),
    "el_landscape_crossings": (_status, [_handle, POINTER(Point), POINTER(Point), _out, _err]),
    "el_landscape_raycast": (_status, [_handle, POINTER(Point), POINTER(Point), POINTER(c_int32),
                                       POINTER(Crossing), _err]),
    "el_landscape_overlaps_box": (_status, [_handle, POINTER(Box), POINTER(c_uint8), _count,
                                            _err]),
    "el_landscape_overlaps_shape": (_status, [_handle, _handle, POINTER(c_uint8), _count, _err]),
    "el_landscape_polygons_in": (_status, [_handle, POINTER(Box), _out, _err]),
    "el_landscape_cells_in": (_status, [_handle, POINTER(Box), POINTER(Box), c_size_t, _count,
                                        _err]),
    "el_landscape_twice_area": (_status, [_handle, c_int32, POINTER(Int128), _err]),
    "el_landscape_world": (_status, [_handle, POINTER(Box), _err]),
    "el_stats_init": (None, [POINTER(Stats)]),
    "el_landscape_stats": (_status, [_handle, POINTER(Stats), _err]),
    "el_landscape_state_hash": (_status, [_handle, POINTER(c_uint64), _err]),
    "el_landscape_check": (_status, [_handle, _out, _err]),
    "el_landscape_set_checked": (_status, [_handle, c_int32, _err]),
    "el_landscape_start_log": (_status, [_handle, _err]),
    "el_landscape_stop_log": (_status, [_handle, _err]),
    "el_landscape_log": (_status, [_handle, _out, _err]),
    "el_landscape_save": (_status, [_handle, _out, _err]),
    "el_landscape_load": (_status, [POINTER(c_uint8), c_size_t, POINTER(LandscapeConfig), _out,
                                    _err]),
    "el_replay_log": (_status, [ctypes.c_char_p, c_size_t, _out, _err]),
    "el_replay_destroy": (None, [_handle]),
    "el_replay_landscape": (_status, [_handle, _out, _err]),
    "el_replay_edits": (c_size_t, [_handle]),
    "el_replay_stopped": (_status, [_handle, _err]),
    "el_replay_report": (_status, [_handle, _out, _err]),
    "el_changes_destroy": (None, [_handle]),
    "el_changes_removed": (POINTER(c_uint64), [_handle, _count]),
    "el_changes_added": (_handle, [_handle]),
    "el_changes_cells": (POINTER(Box), [_handle, _count]),
    "el_changes_area_delta": (POINTER(AreaDelta), [_handle, _count]),
    "el_polygons_destroy": (None, [_handle]),
    "el_polygons_count": (c_size_t, [_handle]),
    "el_polygons_ids": (POINTER(c_uint64), [_handle, _count]),
    "el_polygons_materials": (POINTER(c_uint8), [_handle, _count]),
    "el_polygons_cells": (POINTER(Box), [_handle, _count]),
    "el_polygons_offsets": (POINTER(c_uint32), [_handle, _count]),
    "el_polygons_points": (POINTER(Point), [_handle, _count]),
    "el_crossings_destroy": (None, [_handle]),
    "el_crossings_data": (POINTER(Crossing), [_handle, _count]),
    "el_bytes_destroy": (None, [_handle]),
    "el_physics_materials_init": (None, [POINTER(PhysicsMaterials)]),
    "el_surface_tracker_create": (_status, [_handle, POINTER(PhysicsMaterials), _out, _err]),
    "el_surface_tracker_destroy": (None, [_handle]),
    "el_surface_tracker_update": (_status, [_handle, _handle, _handle, _out, _err]),
    "el_surface_tracker_resync": (_status, [_handle, _handle, _out, _err]),
    "el_surface_tracker_chains": (_status, [_handle, _out, _err]),
    "el_chains_destroy": (None, [_handle]),
    "el_chains_removed": (POINTER(c_uint64), [_handle, _count]),
    "el_chains_info": (POINTER(ChainInfo), [_handle, _count]),
    "el_chains_offsets": (POINTER(c_uint32), [_handle, _count]),
    "el_chains_points": (POINTER(Point), [_handle, _count]),
    "el_chains_materials": (POINTER(c_uint8), [_handle, _count]),
    "el_island_tracker_create": (_status, [_handle, POINTER(PhysicsMaterials), _out, _err]),
    "el_island_tracker_destroy": (None, [_handle]),
    "el_island_tracker_update": (_status, [_handle, _handle, _handle, _out, _err]),
    "el_island_tracker_resync": (_status, [_handle, _handle, _out, _err]),
    "el_island_tracker_islands": (_status, [_handle, _handle, _out, _err]),
    "el_islands_destroy": (None, [_handle]),
    "el_islands_count": (c_size_t, [_handle]),
    "el_islands_info": (POINTER(IslandInfo), [_handle, _count]),
    "el_islands_pieces": (_handle, [_handle]),
    "el_detach": (_status, [_handle, _handle, c_size_t, _out, _err]),
    "el_detached_destroy": (None, [_handle]),
    "el_detached_summary": (_status, [_handle, POINTER(DetachedInfo), _err]),
    "el_detached_changes": (_handle, [_handle]),
    "el_detached_regions": (_handle, [_handle]),
    "el_mesh_update": (_status, [_handle, _out, _err]),
    "el_all_meshes": (_status, [_handle, _out, _err]),
    "el_meshes_destroy": (None, [_handle]),
    "el_meshes_dropped": (POINTER(c_uint64), [_handle, _count]),
    "el_meshes_polygons": (_handle, [_handle]),
    "el_meshes_triangle_offsets": (POINTER(c_uint32), [_handle, _count]),
    "el_meshes_triangles": (POINTER(c_uint32), [_handle, _count]),
    "el_convex_pieces": (_status, [POINTER(Point), c_size_t, c_uint32, _out, _err]),
    "el_bytes_data": (POINTER(c_uint8), [_handle, _count]),
    "el_edits_create": (_status, [_out, _err]),
    "el_edits_destroy": (None, [_handle]),
    "el_edits_carve": (_status, [_handle, _handle, _err]),
    "el_edits_fill": (_status, [_handle, _handle, c_int32, _err]),
    "el_edits_fill_empty": (_status, [_handle, _handle, c_int32, _err]),
    "el_edits_replace": (_status, [_handle, _handle, c_int32, c_int32, _err]),
    "el_edits_relabel": (_status, [_handle, _handle, POINTER(c_int32), c_size_t, _err]),
    "el_game_options_init": (None, [POINTER(GameOptions)]),
    "el_game_driver_create": (_status, [_handle, POINTER(GameOptions), _out, _err]),
    "el_game_driver_destroy": (None, [_handle]),
    "el_game_driver_apply": (_status, [_handle, _handle, _out, _err]),
    "el_game_driver_reset": (_status, [_handle, _handle, _out, _err]),
    "el_game_driver_buried": (_status, [_handle, POINTER(Box), POINTER(c_int32), _err]),
    "el_game_driver_landscape": (_status, [_handle, _out, _err]),
    "el_game_driver_chains": (_status, [_handle, _out, _err]),
    "el_game_driver_debris_waiting": (c_size_t, [_handle]),
    "el_game_work_init": (None, [POINTER(GameWork)]),
    "el_game_update_destroy": (None, [_handle]),
    "el_game_update_changes": (_handle, [_handle]),
    "el_game_update_chains": (_handle, [_handle]),
    "el_game_update_meshes": (_handle, [_handle]),
    "el_game_update_debris": (POINTER(DebrisInfo), [_handle, _count]),
    "el_game_update_debris_regions": (_handle, [_handle]),
    "el_game_update_debris_meshes": (_handle, [_handle]),
    "el_game_update_debris_pieces": (_handle, [_handle]),
    "el_game_update_work": (_status, [_handle, POINTER(GameWork), _err]),
}

for _name, (_restype, _argtypes) in _PROTOTYPES.items():
    _function = getattr(lib, _name)
    _function.restype = _restype
    _function.argtypes = _argtypes


def array(pointer, count):
    """The first `count` elements behind a result's pointer as a list (a copy)."""
    return [pointer[i] for i in range(count)] if count else []
