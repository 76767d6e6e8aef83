"""The game driver (game/README.md, "The game driver") over the C API: one owner of a landscape
and of everything a game derives from it. Each frame's edits go in as one batch; a GameUpdate
comes out: the change set, the collision chains to remove and add (with ghost vertices), the
render meshes to drop and build, and the islands that broke off as Debris bodies."""
import ctypes
from fractions import Fraction
from typing import NamedTuple

from . import _native, results
from ._handles import Handle, Owned, made
from .errors import call
from .game import _BorrowedFrom, _chains, _meshes
from .landscape import Landscape
from .shapes import as_shape

_lib = _native.lib


class Edit(NamedTuple):
    """One edit of a frame's batch (C++ Edit): build it with Edit.carve, .fill, .fill_empty,
    .replace or .relabel; the shape is a Shape or polygons as lists of (x, y)."""
    kind: str
    shape: object
    materials: tuple = ()

    @staticmethod
    def carve(shape):
        return Edit("carve", shape)

    @staticmethod
    def fill(shape, material):
        return Edit("fill", shape, (material,))

    @staticmethod
    def fill_empty(shape, material):
        return Edit("fill_empty", shape, (material,))

    @staticmethod
    def replace(shape, from_material, to_material):
        return Edit("replace", shape, (from_material, to_material))

    @staticmethod
    def relabel(shape, mapping):
        """Inside the shape every material `m` in mapping becomes mapping[m], at once."""
        return Edit("relabel", shape, tuple(mapping.items()))


class MeshUpdate(NamedTuple):
    dropped: list  # polygon ids whose meshes go
    built: list    # Mesh per new polygon


class Debris(NamedTuple):
    """An island taken out of the landscape, ready to become a dynamic body: its region as
    maximal polygons (material, points) per material, their convex pieces (material, points;
    one fixture each), their meshes (with GameDriver(meshes=True)), exact twice area and
    centroid (Fractions), and its bounds."""
    regions: list
    pieces: list
    meshes: list
    twice_area: int
    centroid: tuple
    bounds: tuple


class Work(NamedTuple):
    """What one update did (C++ GameWork) and the islands still waiting."""
    cells_scanned: int
    boundary_passes: int
    cells_traced: int
    islands_found: int
    islands_detached: int
    debris_waiting: int


class GameUpdate(NamedTuple):
    """What one driver call changed: apply it between two physics steps."""
    changes: results.ChangeSet  # every polygon the edits and the detaches removed and added
    chains: object              # ChainUpdate(removed, added): Chains with ghost vertices
    meshes: MeshUpdate
    debris: list                # Debris
    work: Work


def _options(meshes, debris, border_wall, solid, anchored, max_piece_vertices, debris_budget,
             max_debris_wait):
    o = _native.GameOptions()
    _lib.el_game_options_init(ctypes.byref(o))
    o.flags = (1 if meshes else 0) | (2 if debris else 0) | (4 if border_wall else 0)
    if solid is not None:
        for i in range(256):
            o.solid[i] = 1 if i in solid else 0
    for i in anchored:
        o.anchored[i] = 1
    o.max_piece_vertices = max_piece_vertices
    o.debris_budget = debris_budget
    o.max_debris_wait = max_debris_wait
    return o


class _Edits(Handle):
    _destroy = "el_edits_destroy"

    def __init__(self, edits):
        super().__init__(made(_lib.el_edits_create))
        for e in edits:
            self._add(e)

    def _add(self, e):
        shape = as_shape(e.shape)
        if e.kind == "carve":
            call(_lib.el_edits_carve, self, shape)
        elif e.kind in ("fill", "fill_empty"):
            call(getattr(_lib, "el_edits_" + e.kind), self, shape, e.materials[0])
        elif e.kind == "replace":
            call(_lib.el_edits_replace, self, shape, *e.materials)
        elif e.kind == "relabel":
            pairs = (ctypes.c_int32 * (2 * len(e.materials)))(
                *[m for pair in e.materials for m in pair])
            call(_lib.el_edits_relabel, self, shape, pairs, len(e.materials))
        else:
            raise ValueError("unknown edit kind %r" % (e.kind,))


def _debris(h):
    count = ctypes.c_size_t()
    info = _lib.el_game_update_debris(h, ctypes.byref(count))
    regions = results.polygons(_lib.el_game_update_debris_regions(h))
    pieces = results.polygons(_lib.el_game_update_debris_pieces(h))
    _, meshes = _meshes(_lib.el_game_update_debris_meshes(h))
    out = []
    for i in range(count.value):
        d = info[i]
        den = d.centroid_den.value()
        rs = slice(d.first_region, d.first_region + d.region_count)
        ps = slice(d.first_piece, d.first_piece + d.piece_count)
        out.append(Debris([(p.material, p.points) for p in regions[rs]],
                          [(p.material, p.points) for p in pieces[ps]],
                          meshes[rs] if meshes else [], d.twice_area.value(),
                          (Fraction(d.centroid_x_num.value(), den),
                           Fraction(d.centroid_y_num.value(), den)),
                          results.box_tuple(d.bounds)))
    return out


def _update(pointer):
    h = Owned(pointer, "el_game_update_destroy")
    work = _native.GameWork()
    _lib.el_game_work_init(ctypes.byref(work))
    call(_lib.el_game_update_work, h, ctypes.byref(work))
    dropped, built = _meshes(_lib.el_game_update_meshes(h))
    return GameUpdate(results.change_set(_BorrowedFrom(h, _lib.el_game_update_changes(h))),
                      _chains(_lib.el_game_update_chains(h)), MeshUpdate(dropped, built),
                      _debris(h),
                      Work(work.cells_scanned, work.boundary_passes, work.cells_traced,
                           work.islands_found, work.islands_detached, work.debris_waiting))


class GameDriver(Handle):
    """The game driver (C++ GameDriver) over a snapshot of `world` (the Landscape stays the
    caller's own). Options: which materials are `solid` (default every one but 0) and
    `anchored` (never fall), the border as a wall, meshes and debris on or off, the debris
    bodies' convex pieces' `max_piece_vertices` (3 or more; Box2D's 8), the `debris_budget` (island
    vertices one update may detach) and `max_debris_wait` (updates an island may wait)."""

    _destroy = "el_game_driver_destroy"

    def __init__(self, world, meshes=True, debris=True, border_wall=False, solid=None,
                 anchored=(), max_piece_vertices=8, debris_budget=8192, max_debris_wait=3):
        o = _options(meshes, debris, border_wall, solid, anchored, max_piece_vertices,
                     debris_budget, max_debris_wait)
        super().__init__(made(_lib.el_game_driver_create, world, ctypes.byref(o)))

    def apply(self, edits=()):
        """The frame's edits (Edit values), in order, as one batch: the GameUpdate. A typed error
        (InvalidMaterial, LimitExceeded, ...) leaves the driver and its world as they were. No
        edits: only the debris queue moves."""
        with _Edits(edits) as batch:
            return _update(made(_lib.el_game_driver_apply, self, batch))

    def reset(self, world):
        """The world replaced by a snapshot of `world` (an undo, a load): the update names
        exactly what changed."""
        return _update(made(_lib.el_game_driver_reset, self, world))

    def buried(self, box):
        """Whether the last update's fills buried a body whose bounding box is `box`
        ((x0, y0), (x1, y1))."""
        out = ctypes.c_int32()
        b = _native.Box(_native.Point(*box[0]), _native.Point(*box[1]))
        call(_lib.el_game_driver_buried, self, ctypes.byref(b), ctypes.byref(out))
        return bool(out.value)

    @property
    def landscape(self):
        """A snapshot of the driver's world (O(1)): queries, save, state hash."""
        return Landscape(_pointer=made(_lib.el_game_driver_landscape, self))

    @property
    def chains(self):
        """Every chain now, by ascending id."""
        with Owned(made(_lib.el_game_driver_chains, self), "el_chains_destroy") as h:
            return _chains(h).added

    @property
    def debris_waiting(self):
        return _lib.el_game_driver_debris_waiting(self)
