"""edgeland for Python: exact integer 2D landscapes for games and tools.

A pure-Python package over the C API (libedgeland_c) through ctypes; nothing to compile. numpy is
optional (Landscape.polygon_arrays, Shape from arrays). bindings/python/README.md.

    import edgeland
    world = edgeland.Landscape(((0, 0), (1024, 512)), fill=1)
    changes = world.carve(edgeland.Shape.circle((512, 256), 100))
    assert world.material_at((512, 256)) == 0

    game = edgeland.GameDriver(world)                   # what a game uses: chains, meshes, debris
    update = game.apply([edgeland.Edit.fill(edgeland.Shape.circle((512, 400), 20), 2)])
"""
from . import _native
from .errors import (ArgumentOutOfRange, BufferTooSmall, CoordinateOutOfRange, DeltaError,
                     DeltaMismatch, EdgelandError, IndexOutOfRange, InternalError,
                     InvalidArgument, InvalidBox, InvalidConfig, InvalidInput, InvalidMaterial,
                     InvalidOverlay, InvalidPath, LimitExceeded, LoadError, NonPositiveArea,
                     NullArgument, OutOfMemory, RegionNotLoaded, StaleIsland, TooManyVertices,
                     UnknownPolygon, VersionMismatch, BY_STATUS)
from .driver import Debris, Edit, GameDriver, GameUpdate, MeshUpdate, Work
from .game import (Chain, ChainUpdate, IslandTracker, Mesh, SurfaceTracker, all_meshes,
                   convex_pieces, detach, mesh_update)
from .landscape import Landscape
from .replay import Replay, replay_log
from .results import ChangeSet, Crossing, Polygon
from .shapes import Shape


def version():
    """The C library's version as (major, minor, patch)."""
    v = _native.lib.el_version()
    return (v >> 16, (v >> 8) & 0xff, v & 0xff)


if _native.lib.el_check_version(_native.VERSION) != 0:
    raise ImportError("libedgeland_c %d.%d.%d does not serve this package (written for %d.%d)"
                      % (version() + (_native.VERSION >> 16, (_native.VERSION >> 8) & 0xff)))
