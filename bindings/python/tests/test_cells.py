"""Landscape.cells_in (el_landscape_cells_in): the cells' boxes, empty ones too."""
import pytest

import edgeland
from edgeland import Landscape, Shape

WORLD = ((0, 0), (1024, 512))


def area(box):
    (x0, y0), (x1, y1) = box
    return (x1 - x0) * (y1 - y0)


def meets(a, b):
    """Closed boxes meet."""
    return a[0][0] <= b[1][0] and b[0][0] <= a[1][0] and a[0][1] <= b[1][1] and b[0][1] <= a[1][1]


def interiors_meet(a, b):
    return a[0][0] < b[1][0] and b[0][0] < a[1][0] and a[0][1] < b[1][1] and b[0][1] < a[1][1]


@pytest.fixture
def world():
    w = Landscape(WORLD, fill=1, checked=True)
    for k in range(12):  # enough edges to split the root
        w.carve(Shape.circle((40 + 80 * k, 100 + 25 * k), 30))
    yield w
    w.close()


def test_the_cells_tile_the_world(world):
    cells = world.cells_in()
    assert len(cells) == world.stats["cells"] > 1
    assert all(meets(c, WORLD) and area(c) > 0 for c in cells)
    assert all(WORLD[0][0] <= c[0][0] and c[1][0] <= WORLD[1][0] and
               WORLD[0][1] <= c[0][1] and c[1][1] <= WORLD[1][1] for c in cells)
    assert sum(area(c) for c in cells) == area(WORLD)
    assert not any(interiors_meet(a, b) for i, a in enumerate(cells) for b in cells[i + 1:])
    # Every polygon lies in the cell its record names.
    assert {p.cell for p in world.polygons_in()} <= set(cells)


def test_a_box_selects_the_cells_it_meets_in_tree_order(world):
    cells = world.cells_in()
    for box in (((0, 0), (10, 10)), ((500, 200), (700, 300)), ((512, 0), (512, 512))):
        assert world.cells_in(box) == [c for c in cells if meets(c, box)]


def test_empty_cells_are_cells_too():
    empty = Landscape(WORLD, grid_depth=3)  # 8 x 8 cells, all empty space
    cells = empty.cells_in()
    assert empty.polygons_in() == [] and len(cells) == empty.stats["cells"] == 64
    assert {area(c) for c in cells} == {(1024 // 8) * (512 // 8)}


def test_errors_are_typed(world):
    assert world.cells_in(((10, 0), (0, 10))) == []  # an inverted box holds no point
    with pytest.raises(edgeland.CoordinateOutOfRange):
        world.cells_in(((0, 0), (2 ** 40, 10)))
    world.close()
    with pytest.raises(edgeland.NullArgument):
        world.cells_in(WORLD)
