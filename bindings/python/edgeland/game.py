"""The game layer (game/README.md) over the C API: surface chains and debris islands kept in step
from change sets, detach, render meshes, convex pieces. Feed every edit's ChangeSet to every
tracker, in order (detach's too); resync after a restored snapshot or a load."""
import ctypes
from fractions import Fraction
from typing import NamedTuple

from . import _native, results
from ._handles import Handle, Owned, made
from .errors import call

_lib = _native.lib


def _materials(solid=None, anchored=(), border_wall=False):
    """An el_physics_materials: `solid` the materials that collide (default: every one but 0),
    `anchored` those that never fall, `border_wall` the world border as a wall."""
    m = _native.PhysicsMaterials()
    _lib.el_physics_materials_init(ctypes.byref(m))
    if solid is not None:
        for i in range(256):
            m.solid[i] = 1 if i in solid else 0
    for i in anchored:
        m.anchored[i] = 1
    m.flags = 1 if border_wall else 0
    return m


class Chain(NamedTuple):
    """A surface chain: solid on its left, its ghost vertices, the material left of each
    segment (0 after an open chain's last point and along a border wall)."""
    id: int
    points: list
    materials: list
    closed: bool
    ghost_prev: tuple
    ghost_next: tuple
    cell: tuple


class ChainUpdate(NamedTuple):
    removed: list
    added: list


def _chains(handle):
    count = ctypes.c_size_t()
    removed = _native.array(_lib.el_chains_removed(handle, ctypes.byref(count)), count.value)
    info = _lib.el_chains_info(handle, ctypes.byref(count))
    n = count.value
    offsets = _lib.el_chains_offsets(handle, ctypes.byref(count))
    points = _lib.el_chains_points(handle, ctypes.byref(count))
    materials = _lib.el_chains_materials(handle, ctypes.byref(count))
    chains = []
    for i in range(n):
        span = range(offsets[i], offsets[i + 1])
        c = info[i]
        chains.append(Chain(c.id, [(points[k].x, points[k].y) for k in span],
                            [materials[k] for k in span], bool(c.closed),
                            (c.ghost_prev.x, c.ghost_prev.y), (c.ghost_next.x, c.ghost_next.y),
                            results.box_tuple(c.cell)))
    return ChainUpdate(removed, chains)


class SurfaceTracker(Handle):
    """The collision surface as per-cell chains with ghost vertices (C++ SurfaceTracker)."""

    _destroy = "el_surface_tracker_destroy"

    def __init__(self, world, **materials):
        m = _materials(**materials)
        super().__init__(made(_lib.el_surface_tracker_create, world, ctypes.byref(m)))

    def update(self, world, changes):
        """The chains removed and added by the edit that returned `changes`."""
        with Owned(made(_lib.el_surface_tracker_update, self, world, changes._handle),
                   "el_chains_destroy") as h:
            return _chains(h)

    def resync(self, world):
        with Owned(made(_lib.el_surface_tracker_resync, self, world), "el_chains_destroy") as h:
            return _chains(h)

    @property
    def chains(self):
        """Every chain the tracker holds, by ascending id."""
        with Owned(made(_lib.el_surface_tracker_chains, self), "el_chains_destroy") as h:
            return _chains(h).added


class Island(NamedTuple):
    bounds: tuple
    twice_area: int
    pieces: list  # the landscape polygons it is made of


class Islands:
    """Islands found by a tracker; detach() takes one of them by index."""

    def __init__(self, handle):
        self._handle = handle
        count = ctypes.c_size_t()
        info = _lib.el_islands_info(handle, ctypes.byref(count))
        pieces = results.polygons(_lib.el_islands_pieces(handle))
        self.islands = [Island(results.box_tuple(info[i].bounds), info[i].twice_area.value(),
                               pieces[info[i].first_piece:
                                      info[i].first_piece + info[i].piece_count])
                        for i in range(count.value)]

    def __len__(self):
        return len(self.islands)

    def __getitem__(self, i):
        return self.islands[i]


class IslandTracker(Handle):
    """Debris islands found incrementally (C++ IslandTracker)."""

    _destroy = "el_island_tracker_destroy"

    def __init__(self, world, **materials):
        m = _materials(**materials)
        super().__init__(made(_lib.el_island_tracker_create, world, ctypes.byref(m)))

    def update(self, world, changes):
        """The islands that exist now and did not before."""
        return Islands(Owned(made(_lib.el_island_tracker_update, self, world, changes._handle),
                             "el_islands_destroy"))

    def resync(self, world):
        return Islands(Owned(made(_lib.el_island_tracker_resync, self, world),
                             "el_islands_destroy"))

    def islands(self, world):
        return Islands(Owned(made(_lib.el_island_tracker_islands, self, world),
                             "el_islands_destroy"))


class Detached(NamedTuple):
    """An island taken out: the edit's ChangeSet (for the trackers), its region as maximal
    polygons per material (Polygon with id 0), exact twice area and centroid."""
    changes: results.ChangeSet
    regions: list
    twice_area: int
    centroid: tuple


def detach(world, islands, index):
    """Removes islands[index] from the world as one edit (StaleIsland when the world changed
    under it)."""
    h = Owned(made(_lib.el_detach, world, islands._handle, index), "el_detached_destroy")
    info = _native.DetachedInfo()
    call(_lib.el_detached_summary, h, ctypes.byref(info))
    den = info.centroid_den.value()
    return Detached(results.change_set(_BorrowedFrom(h, _lib.el_detached_changes(h))),
                    results.polygons(_lib.el_detached_regions(h)), info.twice_area.value(),
                    (Fraction(info.centroid_x_num.value(), den),
                     Fraction(info.centroid_y_num.value(), den)))


class _BorrowedFrom:
    """A borrowed C pointer that keeps its owner alive."""

    def __init__(self, owner, pointer):
        self._owner = owner
        self._as_parameter_ = ctypes.c_void_p(pointer)


class Mesh(NamedTuple):
    id: int
    material: int
    vertices: list
    triangles: list  # (a, b, c) index triples into vertices, counter-clockwise


def _meshes(handle):
    count = ctypes.c_size_t()
    dropped = _native.array(_lib.el_meshes_dropped(handle, ctypes.byref(count)), count.value)
    polygons = results.polygons(_lib.el_meshes_polygons(handle))
    offsets = _lib.el_meshes_triangle_offsets(handle, ctypes.byref(count))
    triangles = _lib.el_meshes_triangles(handle, ctypes.byref(count))
    meshes = [Mesh(p.id, p.material, p.points,
                   [(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2])
                    for t in range(offsets[i], offsets[i + 1])])
              for i, p in enumerate(polygons)]
    return dropped, meshes


def mesh_update(changes):
    """(ids of the meshes to drop, meshes to build) for an edit's change set."""
    with Owned(made(_lib.el_mesh_update, changes._handle), "el_meshes_destroy") as h:
        return _meshes(h)


def all_meshes(world):
    with Owned(made(_lib.el_all_meshes, world), "el_meshes_destroy") as h:
        return _meshes(h)[1]


def convex_pieces(polygon, max_vertices=8):
    """A valid polygon as strictly convex pieces of at most max_vertices vertices."""
    points = (_native.Point * len(polygon))(*[_native.Point(x, y) for x, y in polygon])
    with Owned(made(_lib.el_convex_pieces, points, len(polygon), max_vertices),
               "el_polygons_destroy") as h:
        return [p.points for p in results.polygons(h)]
