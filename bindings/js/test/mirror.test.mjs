// The mirror script (tests/mirror/README.md) from JavaScript, against the C++ run's hashes (the
// file in $EDGELAND_MIRROR_HASHES, written by ctest's mirror.cpp). ctest mirror.js.
import assert from 'node:assert/strict';
import {readFileSync} from 'node:fs';
import {test} from 'node:test';

import * as edgeland from '../index.js';
import {Landscape, Shape} from '../index.js';

const MASK = (1n << 64n) - 1n;
let s = 36n;
function next() {
  s = (s + 0x9E3779B97F4A7C15n) & MASK;
  let z = s;
  z = ((z ^ (z >> 30n)) * 0xBF58476D1CE4E5B9n) & MASK;
  z = ((z ^ (z >> 27n)) * 0x94D049BB133111EBn) & MASK;
  return z ^ (z >> 31n);
}
const below = (n) => Number(next() % BigInt(n));

function drawShape() {
  const kind = below(3);
  const c = [below(2176) - 64, below(1152) - 64];
  const r = 4 + below(60);
  if (kind === 0) return Shape.circle(c, r);
  if (kind === 1) {
    const h = 1 + Math.floor(r / 2);
    return Shape.box([c[0] - r, c[1] - h], [c[0] + r, c[1] + h]);
  }
  const sides = 3 + below(6);
  return Shape.regularPolygon(c, r, sides, [below(16), 16]);
}

function drawEdit(world) {
  const op = below(5);
  const shape = drawShape();
  try {
    if (op === 0) return world.carve(shape);
    if (op === 1) return world.fill(shape, 1 + below(4));
    if (op === 2) return world.fillEmpty(shape, 1 + below(4));
    if (op === 3) {
      const from = below(5);
      return world.replace(shape, from, below(5));
    }
    const pairs = [];
    for (let i = 0; i < 2; ++i) {
      const from = below(5);
      pairs.push([from, below(5)]);
    }
    return world.relabel(shape, pairs);
  } finally {
    shape.dispose();
  }
}

const key = (p) => `${p.material}:${p.points.join(';')}`;
function polygonsOf(world) {
  const m = new Map();
  for (const p of world.polygonsIn()) m.set(p.id, key(p));
  return m;
}
const same = (a, b) => a.size === b.size && [...a].every(([id, v]) => b.get(id) === v);

function badInput(world) {
  const before = world.stateHash;
  assert.throws(() => world.fill([[[0, 0], [10, 10], [10, 0], [0, 10]]], 2),
    (e) => e instanceof edgeland.InvalidInput && e.rule === 'self-intersection');
  assert.throws(() => world.fill([[[0, 0], [10, 0], [10, 10], [0, 10]]], 300),
    (e) => e instanceof edgeland.InvalidMaterial && e.value === 300);
  assert.equal(world.stateHash, before);
}

test('the mirror reaches the C++ run\'s hashes', () => {
  const expected = readFileSync(process.env.EDGELAND_MIRROR_HASHES, 'utf8').trim().split('\n')
    .map((line) => line.split(' '));
  assert.equal(expected.length, 5000);
  let world = new Landscape([[0, 0], [2048, 1024]], 1);
  let mirror = polygonsOf(world);
  let snapshot = null, mirrorSnapshot = null;
  for (let f = 0; f < 5000; ++f) {
    if (f % 1000 === 500) badInput(world);
    const edits = 1 + below(3);
    for (let e = 0; e < edits; ++e) {
      const changes = drawEdit(world);
      for (const id of changes.removed) assert.ok(mirror.delete(id), `frame ${f}: id ${id}`);
      for (const p of changes.added) mirror.set(p.id, key(p));
      changes.dispose();
    }
    if (f % 100 === 90) {
      snapshot?.dispose();
      snapshot = world.clone();
      mirrorSnapshot = new Map(mirror);
    }
    if (f % 100 === 99) {
      world.dispose();
      world = snapshot.clone();
      mirror = new Map(mirrorSnapshot);
    }
    if (f % 500 === 499) {
      const bytes = world.save();
      world.dispose();
      world = Landscape.load(bytes);
    }
    assert.deepEqual(expected[f], [String(f), String(world.stateHash)], `frame ${f}`);
    if (f % 100 === 99 || f === 4999) assert.ok(same(mirror, polygonsOf(world)), `mirror at frame ${f}`);
  }
  world.dispose();
  snapshot.dispose();
});
