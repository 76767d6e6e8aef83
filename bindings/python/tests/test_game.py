"""The game layer from Python: chains and islands in step with edits, detach, meshes, pieces."""
from fractions import Fraction

import pytest

import edgeland
from edgeland import IslandTracker, Landscape, Shape, SurfaceTracker


def square(x, y, side):
    return [[(x, y), (x + side, y), (x + side, y + side), (x, y + side)]]


def test_trackers_follow_edits_and_detach():
    world = Landscape(((0, 0), (1024, 512)))
    surface, islands = SurfaceTracker(world), IslandTracker(world)
    changes = world.fill(square(0, 0, 100), 1)  # on the border: held
    update = surface.update(world, changes)
    assert update.added and update.added[0].materials[0] == 1 and not update.added[0].closed
    assert len(islands.update(world, changes)) == 0

    changes = world.fill(square(400, 300, 40), 2)  # floating
    chains = surface.update(world, changes).added
    assert len(chains) == 1 and chains[0].closed
    found = islands.update(world, changes)
    assert len(found) == 1 and found[0].twice_area == 3200
    assert {p.material for p in found[0].pieces} == {2}
    dropped, built = edgeland.mesh_update(changes)
    assert len(built) == 1 and len(built[0].triangles) == 2

    detached = edgeland.detach(world, found, 0)
    assert detached.twice_area == 3200 and detached.centroid == (Fraction(420), Fraction(320))
    assert [p.material for p in detached.regions] == [2]
    assert world.material_at((420, 320)) == 0
    assert surface.update(world, detached.changes).removed == [chains[0].id]
    assert len(islands.update(world, detached.changes)) == 0
    with pytest.raises(edgeland.StaleIsland):
        edgeland.detach(world, found, 0)
    with pytest.raises(edgeland.IndexOutOfRange):
        edgeland.detach(world, found, 1)
    def shapes(chains):
        return sorted((c.points, c.materials, c.closed, c.ghost_prev, c.ghost_next)
                      for c in chains)
    assert shapes(surface.chains) == shapes(SurfaceTracker(world).chains)  # in step
    assert len(edgeland.all_meshes(world)) == len(world.polygons_in())


def test_materials_tables_and_walls():
    world = Landscape(((0, 0), (256, 256)))
    world.fill(square(100, 100, 20), 3)
    assert len(IslandTracker(world).islands(world)) == 1
    assert len(IslandTracker(world, anchored={3}).islands(world)) == 0
    assert SurfaceTracker(world, solid={1}).chains == []
    walls = SurfaceTracker(world, border_wall=True).chains
    assert any(0 in c.materials[:-1] for c in walls)


def test_convex_pieces():
    ell = [(0, 0), (20, 0), (20, 10), (10, 10), (10, 20), (0, 20)]
    assert len(edgeland.convex_pieces(ell)) == 2
    assert len(edgeland.convex_pieces(ell, 3)) == 4
    with pytest.raises(edgeland.InvalidArgument):
        edgeland.convex_pieces(ell, 2)
    with pytest.raises(edgeland.InvalidInput):
        edgeland.convex_pieces([(0, 0), (10, 10), (10, 0), (0, 10)])
