"""Shape.import_polygons (el_shape_import): rings as others draw them, read with OGC semantics."""
import pytest

import edgeland
from edgeland import Landscape, Shape

EL_OPERAND_RINGS = 2  # edgeland.h: the operand of an import's error


def twice_area(ring):
    """Twice the signed area of a ring (shoelace): positive when counter-clockwise."""
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))


def filled(shape, world=((0, 0), (256, 256))):
    """An empty world with the shape filled as material 2."""
    w = Landscape(world, checked=True)
    w.fill(shape, 2)
    return w


def assert_valid(shape):
    """The pieces are a valid set: counter-clockwise, and el_shape_create takes them as they are
    (it validates every rule: strictly simple, hole-free, disjoint interiors)."""
    polygons = shape.polygons
    assert all(twice_area(p) > 0 for p in polygons)
    with Shape(polygons) as again:
        assert again.polygons == polygons


def test_a_bow_tie_is_its_two_lobes():
    bow_tie = [[(0, 0), (100, 100), (100, 0), (0, 100)]]
    with pytest.raises(edgeland.InvalidInput):
        Shape(bow_tie)  # not a valid set as drawn
    shape = Shape.import_polygons([bow_tie])
    assert_valid(shape)
    assert len(shape.polygons) == 2
    # OGC: the region the ring winds around is the two triangles meeting where the edges cross.
    lobes = [[(0, 0), (50, 50), (0, 100)], [(50, 50), (100, 100), (100, 0)]]
    ogc = sum(abs(twice_area(lobe)) for lobe in lobes)
    assert sum(twice_area(p) for p in shape.polygons) == ogc
    world = filled(shape)
    assert world.twice_area(2) == ogc
    assert world.material_at((10, 50)) == 2 and world.material_at((90, 50)) == 2
    assert world.material_at((50, 10)) == 0 and world.material_at((50, 90)) == 0


def test_a_clockwise_ring_is_accepted_and_turned():
    clockwise = [(0, 0), (0, 10), (10, 10), (10, 0)]
    assert twice_area(clockwise) < 0
    with pytest.raises(edgeland.InvalidInput) as e:
        Shape([clockwise])
    assert e.value.rule == "not-counter-clockwise"
    shape = Shape.import_polygons([[clockwise]])
    assert_valid(shape)
    [ring] = shape.polygons
    assert sorted(ring) == sorted(clockwise) and twice_area(ring) == -twice_area(clockwise)


def test_a_holed_square_becomes_hole_free_pieces_of_its_area():
    outer = [(0, 0), (30, 0), (30, 30), (0, 30)]
    hole = [(10, 10), (20, 10), (20, 20), (10, 20)]
    for hole_drawn in (hole, hole[::-1]):  # a hole's orientation does not matter
        shape = Shape.import_polygons([[outer, hole_drawn]])
        assert_valid(shape)
        assert len(shape.polygons) >= 2  # a ring region needs at least two hole-free pieces
        assert sum(twice_area(p) for p in shape.polygons) == 2 * (30 * 30 - 10 * 10)
        world = filled(shape, ((0, 0), (64, 64)))
        assert world.twice_area(2) == 2 * (30 * 30 - 10 * 10)
        assert world.material_at((15, 15)) == 0 and world.material_at((5, 5)) == 2
        assert world.check() == []


def test_overlapping_polygons_are_their_union():
    a = [(0, 0), (10, 0), (10, 10), (0, 10)]
    b = [(5, 5), (15, 5), (15, 15), (5, 15)]
    shape = Shape.import_polygons([[a], [b]])
    assert_valid(shape)
    assert sum(twice_area(p) for p in shape.polygons) == 2 * (100 + 100 - 25)


def test_numpy_rings_and_rings_of_no_area():
    import numpy
    square = numpy.array([(0, 0), (0, 8), (8, 8), (8, 0)], dtype=numpy.int64)
    assert sum(twice_area(p) for p in Shape.import_polygons([[square]]).polygons) == 128
    assert Shape.import_polygons([[[(0, 0), (10, 0), (20, 0)]]]).polygons == []
    assert Shape.import_polygons([]).polygons == []


def test_a_coordinate_out_of_range_names_its_polygon_and_vertex():
    square = [(0, 0), (5, 0), (5, 5), (0, 5)]
    with pytest.raises(edgeland.CoordinateOutOfRange) as e:
        Shape.import_polygons([[square], [[(0, 0), (2 ** 40, 0), (0, 10)]]])
    assert e.value.operand == EL_OPERAND_RINGS
    assert e.value.index == 1 and e.value.vertex == 1 and e.value.where == (2 ** 40, 0)
