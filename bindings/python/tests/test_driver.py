"""The game driver from Python: a frame's edits in, chains (with ghosts), meshes and debris out;
buried bodies; reset to a snapshot; typed errors that leave the driver as it was."""
from fractions import Fraction

import pytest

import edgeland
from edgeland import Edit, GameDriver, Landscape, Shape


def cell_world(**limits):
    """An empty world of 8 x 8 cells, so the ground's surface crosses cell lines."""
    return Landscape(((0, 0), (1024, 512)), grid_depth=3, checked=True, **limits)


def box(x0, y0, x1, y1):
    return Shape.box((x0, y0), (x1, y1))


class ChainMirror:
    """The chains a game holds, kept from the updates alone."""

    def __init__(self, chains=()):
        self.chains = {c.id: c for c in chains}

    def apply(self, update):
        for chain_id in update.removed:
            del self.chains[chain_id]  # a KeyError: an id the game never got
        for c in update.added:
            assert c.id not in self.chains
            self.chains[c.id] = c

    def matches(self, game):
        return self.chains == {c.id: c for c in game.chains}


def test_a_frame_gives_chains_meshes_and_debris():
    world = cell_world()
    game = GameDriver(world)
    mirror = ChainMirror(game.chains)
    update = game.apply([Edit.fill(box(0, 0, 1024, 100), 1),     # ground, held by the border
                         Edit.fill(box(400, 300, 440, 340), 2)])  # a rock in the air
    mirror.apply(update.chains)
    assert mirror.matches(game)

    [rock] = update.debris
    assert rock.twice_area == 3200 and rock.centroid == (Fraction(420), Fraction(320))
    assert rock.bounds == ((400, 300), (440, 340))
    assert [m for m, _ in rock.regions] == [2] and len(rock.pieces) == 1
    assert rock.pieces[0][0] == 2 and len(rock.pieces[0][1]) == 4
    assert len(rock.meshes) == 1 and len(rock.meshes[0].triangles) == 2
    assert game.landscape.material_at((420, 320)) == 0
    assert world.material_at((420, 320)) == 0 and world.material_at((10, 10)) == 0  # its own

    # Meshes for every polygon the update added; the work it did.
    assert sorted(m.id for m in update.meshes.built) == sorted(p.id for p in update.changes.added)
    assert update.work.islands_detached == 1 and update.work.cells_scanned >= 1

    # Where one chain ends at a cell line the next begins, each one's ghost the other's point.
    chains = [c for c in game.chains if not c.closed]
    joints = 0
    for a in chains:
        for b in chains:
            if a is not b and a.points[-1] == b.points[0]:
                assert a.ghost_next == b.points[1] and b.ghost_prev == a.points[-2]
                joints += 1
    assert joints == 7  # the ground's top crosses 7 cell lines


def test_buried_reset_and_snapshot():
    game = GameDriver(cell_world())
    mirror = ChainMirror(game.chains)
    mirror.apply(game.apply([Edit.fill(box(0, 0, 1024, 100), 1)]).chains)
    mirror.apply(game.apply([Edit.fill(box(600, 60, 650, 250), 3)]).chains)
    assert game.buried(((610, 210), (620, 220)))
    assert not game.buried(((100, 400), (110, 410)))

    before = game.landscape
    mirror.apply(game.apply([Edit.carve(Shape.circle((300, 100), 60))]).chains)
    assert game.landscape.state_hash != before.state_hash and mirror.matches(game)
    update = game.reset(before)
    mirror.apply(update.chains)
    assert game.landscape.state_hash == before.state_hash and mirror.matches(game)
    assert update.changes.removed  # the crater's polygons went


def test_edits_of_every_kind_and_polygons_as_lists():
    game = GameDriver(Landscape(((0, 0), (256, 256)), fill=1))
    square = [[(100, 100), (150, 100), (150, 150), (100, 150)]]
    game.apply([Edit.carve(square), Edit.fill_empty(square, 2), Edit.replace(square, 2, 3),
                Edit.relabel(square, {3: 4, 1: 5})])
    assert game.landscape.material_at((120, 120)) == 4
    assert game.landscape.material_at((10, 10)) == 1
    assert game.apply().debris == []  # no edits: only the debris queue moves


def test_errors_leave_the_driver_as_it_was():
    with pytest.raises(edgeland.InvalidArgument) as e:
        GameDriver(cell_world(), max_piece_vertices=2)
    assert e.value.value == 2 and e.value.minimum == 3

    game = GameDriver(cell_world(max_shape_vertices=16))
    hash_before, chains_before = game.landscape.state_hash, game.chains
    with pytest.raises(edgeland.InvalidMaterial) as e:
        game.apply([Edit.carve(box(10, 10, 50, 50)), Edit.fill(box(10, 10, 50, 50), 300)])
    assert e.value.value == 300
    with pytest.raises(edgeland.LimitExceeded) as e:
        game.apply([Edit.carve(box(10, 10, 50, 50)), Edit.fill(Shape.circle((500, 300), 100), 1)])
    assert e.value.limit == 16 and e.value.limit_name == "shape-vertices"
    assert game.landscape.state_hash == hash_before and game.chains == chains_before
    with pytest.raises(edgeland.InvalidInput):
        game.apply([Edit.fill([[(0, 0), (10, 10), (10, 0), (0, 10)]], 2)])  # a bow tie
    assert game.landscape.state_hash == hash_before


def test_options():
    world = cell_world()
    game = GameDriver(world, max_piece_vertices=3, meshes=False)
    update = game.apply([Edit.fill(box(400, 300, 440, 340), 4)])
    assert len(update.debris[0].pieces) == 2 and update.debris[0].meshes == []
    assert update.meshes.built == []
    kept = GameDriver(world, debris=False)
    still = kept.apply([Edit.fill(box(400, 300, 440, 340), 4)])
    assert still.debris == [] and kept.landscape.material_at((420, 320)) == 4
    assert len(still.chains.added) == 2  # the rock's outline, cut at the cell line y = 320
    anchored = GameDriver(world, anchored={4}).apply([Edit.fill(box(400, 300, 440, 340), 4)])
    assert anchored.debris == []
    walls = GameDriver(world, border_wall=True)
    assert any(0 in c.materials[:-1] for c in walls.chains)
