"""The mirror script (tests/mirror/README.md) from Python, against the C++ run's hashes (the file
in $EDGELAND_MIRROR_HASHES, written by ctest's mirror.cpp)."""
import os

import pytest

import edgeland
from edgeland import Landscape, Shape

MASK = (1 << 64) - 1


class Random:
    """splitmix64, as every language's run draws it."""

    def __init__(self):
        self.s = 36

    def next(self):
        self.s = (self.s + 0x9E3779B97F4A7C15) & MASK
        z = self.s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def below(self, n):
        return self.next() % n


def draw_shape(r):
    kind = r.below(3)
    cx, cy = r.below(2176) - 64, r.below(1152) - 64
    radius = 4 + r.below(60)
    if kind == 0:
        return Shape.circle((cx, cy), radius)
    if kind == 1:
        h = 1 + radius // 2
        return Shape.box((cx - radius, cy - h), (cx + radius, cy + h))
    sides = 3 + r.below(6)
    return Shape.regular_polygon((cx, cy), radius, sides, (r.below(16), 16))


def draw_edit(r, world):
    op = r.below(5)
    with draw_shape(r) as shape:
        if op == 0:
            return world.carve(shape)
        if op == 1:
            return world.fill(shape, 1 + r.below(4))
        if op == 2:
            return world.fill_empty(shape, 1 + r.below(4))
        if op == 3:
            source = r.below(5)
            return world.replace(shape, source, r.below(5))
        mapping = {}
        for _ in range(2):
            source = r.below(5)
            mapping[source] = r.below(5)
        return world.relabel(shape, mapping)


def polygons_of(world):
    return {p.id: (p.material, p.points) for p in world.polygons_in()}


def bad_input(world):
    before = world.state_hash
    with pytest.raises(edgeland.InvalidInput) as e:
        world.fill([[(0, 0), (10, 10), (10, 0), (0, 10)]], 2)
    assert e.value.rule == "self-intersection"
    with pytest.raises(edgeland.InvalidMaterial) as e:
        world.fill([[(0, 0), (10, 0), (10, 10), (0, 10)]], 300)
    assert e.value.value == 300
    assert world.state_hash == before


def test_mirror_reaches_the_cpp_runs_hashes():
    with open(os.environ["EDGELAND_MIRROR_HASHES"]) as f:
        expected = [tuple(int(v) for v in line.split()) for line in f]
    assert len(expected) == 5000
    r = Random()
    world = Landscape(((0, 0), (2048, 1024)), fill=1)
    mirror = polygons_of(world)
    snapshot, mirror_snapshot = None, None
    for f in range(5000):
        if f % 1000 == 500:
            bad_input(world)
        for _ in range(1 + r.below(3)):
            changes = draw_edit(r, world)
            for gone in changes.removed:
                del mirror[gone]
            for p in changes.added:
                mirror[p.id] = (p.material, p.points)
        if f % 100 == 90:
            snapshot, mirror_snapshot = world.copy(), dict(mirror)
        if f % 100 == 99:
            world, mirror = snapshot.copy(), dict(mirror_snapshot)
        if f % 500 == 499:
            world = Landscape.load(world.save())
        assert expected[f] == (f, world.state_hash), "frame %d" % f
        if f % 100 == 99 or f == 4999:
            assert mirror == polygons_of(world), "mirror at frame %d" % f
