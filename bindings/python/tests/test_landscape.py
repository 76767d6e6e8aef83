"""The Python package on the C library: edits, change sets, queries, errors, snapshots, saves."""
from fractions import Fraction

import pytest

import edgeland
from edgeland import Landscape, Shape

WORLD = ((0, 0), (1024, 512))


def square(x, y, side):
    return [[(x, y), (x + side, y), (x + side, y + side), (x, y + side)]]


@pytest.fixture
def world():
    w = Landscape(WORLD, fill=1, checked=True)
    yield w
    w.close()


def test_version_is_the_one_the_package_was_written_for():
    assert edgeland.version()[0] == 1


def test_a_carve_reports_what_it_changed(world):
    before = world.twice_area(1)
    changes = world.carve(Shape.circle((512, 256), 100))
    assert changes.removed and changes.added and changes.cells
    assert sum(changes.area_delta.values()) == 0
    assert world.twice_area(1) == before + changes.area_delta[1]
    assert world.twice_area(0) == -changes.area_delta[1] > 0
    assert world.material_at((512, 256)) == 0
    ids = {p.id for p in world.polygons_in()}
    assert ids.isdisjoint(changes.removed) and {p.id for p in changes.added} <= ids


def test_a_bad_shape_is_a_typed_error_and_changes_nothing(world):
    before = world.state_hash
    with pytest.raises(edgeland.InvalidInput) as bad:
        world.fill([[(0, 0), (10, 10), (10, 0), (0, 10)]], 2)  # a bow tie
    assert bad.value.rule == "self-intersection" and bad.value.index == 0
    with pytest.raises(edgeland.CoordinateOutOfRange) as far:
        Shape([[(0, 0), (3_000_000_000, 0), (0, 10)]])
    assert far.value.vertex == 1 and far.value.where == (3_000_000_000, 0)
    with pytest.raises(edgeland.InvalidMaterial) as material:
        world.fill(square(10, 10, 20), 300)
    assert material.value.value == 300
    with pytest.raises(edgeland.ArgumentOutOfRange):
        Shape.circle((0, 0), 0)
    assert world.state_hash == before


def test_configuration_errors_name_the_setting():
    with pytest.raises(edgeland.InvalidConfig) as e:
        Landscape(((10, 0), (0, 10)))
    assert e.value.setting == "world-empty"
    with pytest.raises(edgeland.InvalidConfig) as e:
        Landscape(WORLD, edge_cap=8)
    assert e.value.setting == "edge-cap"
    small = Landscape(((0, 0), (100, 100)), max_shape_vertices=3)
    with pytest.raises(edgeland.LimitExceeded) as e:
        small.fill(square(0, 0, 10), 2)
    assert e.value.limit_name == "shape-vertices" and e.value.limit == 3 and e.value.value == 4


def test_queries_are_exact(world):
    world.carve(square(100, 100, 50))
    world.fill(square(300, 100, 20), 3)
    hit = world.raycast((120, 125), (120, 400))
    assert hit.point == (Fraction(120), Fraction(150)) and hit.after == 1 and hit.before == 0
    assert hit.t == Fraction(25, 275)
    assert [c.after for c in world.crossings((120, 125), (120, 400))] == [1]
    assert world.raycast((120, 125), (120, 140)) is None
    assert world.overlaps(((90, 90), (160, 160))) == [1]
    assert world.overlaps(((0, 0), (400, 200))) == [1, 3]
    assert world.overlaps(square(100, 100, 50)) == []
    with pytest.raises(edgeland.CoordinateOutOfRange):
        world.material_at((0, -3_000_000_000))


def test_snapshots_saves_and_loads(world):
    snapshot = world.copy()
    world.carve(Shape.box((100, 100), (150, 150)))
    assert snapshot.state_hash != world.state_hash
    assert snapshot.material_at((120, 120)) == 1
    data = world.save()
    loaded = Landscape.load(data)
    assert loaded.state_hash == world.state_hash
    assert loaded.polygons_in() == world.polygons_in()
    broken = bytearray(data)
    broken[len(broken) // 2] ^= 0x40
    with pytest.raises(edgeland.LoadError):
        Landscape.load(bytes(broken))
    with pytest.raises(edgeland.LoadError) as junk:
        Landscape.load(b"\x01\x02\x03")
    assert junk.value.index <= 3
    assert world.check() == []


def test_relabel_swaps_materials_at_once(world):
    world.start_log()
    world.fill(square(300, 100, 20), 3)
    world.relabel(square(0, 0, 512), {1: 3, 3: 1})
    assert world.material_at((310, 110)) == 1 and world.material_at((10, 10)) == 3
    assert world.log.startswith("world 0 0 1024 512 1\n")


def test_shape_builders():
    assert len(Shape.regular_polygon((0, 0), 50, 6).polygons[0]) == 6
    assert Shape.capsule((0, 0), (100, 0), 10).polygons
    assert Shape.rotated_box((0, 0), 10, 5, (1, 8)).polygons
    assert Shape(square(0, 0, 5)).polygons == square(0, 0, 5)


def test_numpy_arrays(world):
    import numpy
    world.fill(square(300, 100, 20), 3)
    ids, materials, offsets, points = world.polygon_arrays()
    polygons = world.polygons_in()
    assert list(ids) == [p.id for p in polygons]
    assert offsets[-1] == len(points) and points.shape[1] == 2
    assert numpy.array_equal(points[offsets[0]:offsets[1]], numpy.array(polygons[0].points))
    assert Shape([numpy.array(square(0, 0, 5)[0])]).polygons == square(0, 0, 5)


def test_closed_objects_refuse_use(world):
    shape = Shape.circle((10, 10), 5)
    shape.close()
    with pytest.raises(edgeland.NullArgument):
        world.carve(shape)


def test_every_status_the_library_names_has_its_exception():
    # The C library names its statuses (el_status_name); each but EL_OK maps to its own class.
    from edgeland import _native
    named = {s for s in range(1, 256)
             if _native.lib.el_status_name(s) != b"EL_UNKNOWN"}
    assert {24, 25, 26, 27, 28} <= named
    assert named == set(edgeland.BY_STATUS)
    assert edgeland.BY_STATUS[27] is edgeland.RegionNotLoaded
