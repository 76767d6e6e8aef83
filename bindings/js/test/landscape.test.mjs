// The JavaScript package (index.js) in Node's test runner: edits, change sets, queries, errors,
// snapshots, saves. ctest bindings.js.
import assert from 'node:assert/strict';
import {test} from 'node:test';

import * as edgeland from '../index.js';
import {Landscape, Shape} from '../index.js';

const WORLD = [[0, 0], [1024, 512]];
const square = (x, y, side) => [[[x, y], [x + side, y], [x + side, y + side], [x, y + side]]];

function withWorld(fn) {
  const world = new Landscape(WORLD, 1, {checked: true});
  try {
    fn(world);
  } finally {
    world.dispose();
  }
}

test('the library is the version the package was written for', () => {
  assert.equal(edgeland.version()[0], 1);
});

test('a carve reports what it changed', () => withWorld((world) => {
  const before = world.twiceArea(1);
  const changes = world.carve(Shape.circle([512, 256], 100));
  assert.ok(changes.removed.length > 0 && changes.added.count > 0 && changes.cells.length > 0);
  assert.equal([...changes.areaDelta.values()].reduce((a, b) => a + b, 0n), 0n);
  assert.equal(world.twiceArea(1), before + changes.areaDelta.get(1));
  assert.equal(world.materialAt([512, 256]), 0);
  const ids = new Set(world.polygonsIn().ids);
  for (const id of changes.removed) assert.ok(!ids.has(id));
  for (const p of changes.added) assert.ok(ids.has(p.id));
}));

test('a bad shape is a typed error and changes nothing', () => withWorld((world) => {
  const before = world.stateHash;
  assert.throws(() => world.fill([[[0, 0], [10, 10], [10, 0], [0, 10]]], 2), (e) =>
    e instanceof edgeland.InvalidInput && e.rule === 'self-intersection' && e.index === 0);
  assert.throws(() => new Shape([[[0, 0], [3000000000, 0], [0, 10]]]), (e) =>
    e instanceof edgeland.CoordinateOutOfRange && e.vertex === 1 && e.where[0] === 3000000000);
  assert.throws(() => world.fill(square(10, 10, 20), 300), (e) =>
    e instanceof edgeland.InvalidMaterial && e.value === 300);
  assert.throws(() => Shape.circle([0, 0], 0), edgeland.ArgumentOutOfRange);
  assert.throws(() => new Landscape([[10, 0], [0, 10]]), edgeland.InvalidConfig);
  assert.throws(() => world.materialAt([0, -3000000000]), edgeland.CoordinateOutOfRange);
  assert.equal(world.stateHash, before);
}));

test('queries are exact', () => withWorld((world) => {
  world.carve(square(100, 100, 50));
  world.fill(square(300, 100, 20), 3);
  const hit = world.raycast([120, 125], [120, 400]);
  assert.deepEqual(hit.rounded, [120, 150]);
  assert.equal(hit.point.y, 150n * hit.point.den);
  assert.equal(hit.t.num * 275n, hit.t.den * 25n);
  assert.equal(hit.after, 1);
  assert.equal(world.raycast([120, 125], [120, 140]), null);
  assert.equal(world.crossings([120, 125], [120, 400]).length, 1);
  assert.deepEqual(world.overlaps([[0, 0], [400, 200]]), [1, 3]);
  assert.deepEqual(world.overlaps(square(100, 100, 50)), []);
}));

test('the cells tile the world, empty ones too', () => withWorld((world) => {
  for (let k = 0; k < 12; ++k) world.carve(Shape.circle([40 + 80 * k, 100 + 25 * k], 30));
  const cells = world.cellsIn();
  assert.equal(cells.length / 4, world.stats.cells);
  assert.ok(world.stats.cells > 1);
  let area = 0;
  for (let k = 0; k < cells.length; k += 4) area += (cells[k + 2] - cells[k]) * (cells[k + 3] - cells[k + 1]);
  assert.equal(area, 1024 * 512);
  assert.ok(world.cellsIn([[0, 0], [10, 10]]).length >= 4);
}));

test('snapshots, saves and loads', () => withWorld((world) => {
  const snapshot = world.clone();
  world.carve(Shape.box([100, 100], [150, 150]));
  assert.notEqual(snapshot.stateHash, world.stateHash);
  assert.equal(snapshot.materialAt([120, 120]), 1);
  snapshot.dispose();
  const bytes = world.save();
  const loaded = Landscape.load(bytes);
  assert.equal(loaded.stateHash, world.stateHash);
  assert.deepEqual([...loaded.polygonsIn()], [...world.polygonsIn()]);
  loaded.dispose();
  bytes[bytes.length >> 1] ^= 0x40;
  assert.throws(() => Landscape.load(bytes), edgeland.LoadError);
  assert.deepEqual(world.check(), []);
}));

test('relabel swaps materials at once, and the log records it', () => withWorld((world) => {
  world.startLog();
  world.fill(square(300, 100, 20), 3);
  world.relabel(square(0, 0, 512), [[1, 3], [3, 1]]);
  assert.equal(world.materialAt([310, 110]), 1);
  assert.equal(world.materialAt([10, 10]), 3);
  assert.ok(world.log.startsWith('world 0 0 1024 512 1\n'));
}));

test('shape builders and disposed objects', () => {
  assert.equal(Shape.regularPolygon([0, 0], 50, 6).polygons[0].length, 6);
  assert.deepEqual(new Shape(square(0, 0, 5)).polygons, square(0, 0, 5));
  const s = Shape.capsule([0, 0], [100, 0], 10);
  s.dispose();
  withWorld((world) => assert.throws(() => world.carve(s), (e) => e.status === 1));
});

test('the OGC import takes rings as drawn', () => {
  const bowTie = Shape.import([[[[0, 0], [100, 100], [100, 0], [0, 100]]]]);
  assert.equal(bowTie.polygons.length, 2);
  const clockwise = Shape.import([[[[0, 0], [0, 10], [10, 10], [10, 0]]]]);
  assert.deepEqual(clockwise.polygons, square(0, 0, 10));
  const holed = Shape.import([[square(0, 0, 30)[0], square(10, 10, 10)[0]]]);
  const world = new Landscape([[0, 0], [64, 64]]);
  world.fill(holed, 2);
  assert.equal(world.twiceArea(2), 2n * (900n - 100n));
  assert.equal(Shape.import([[[[0, 0], [10, 0], [20, 0]]]]).polygons.length, 0);
  assert.throws(() => Shape.import([square(0, 0, 5), [[[0, 0], [2 ** 40, 0], [0, 10]]]]), (e) =>
    e instanceof edgeland.CoordinateOutOfRange && e.index === 1 && e.vertex === 1);
  for (const s of [bowTie, clockwise, holed, world]) s.dispose();
});

test('a recorded log replays to the same world, which records itself again', () => withWorld((world) => {
  world.startLog();
  world.carve(Shape.circle([512, 256], 100));
  world.fill(square(100, 100, 50), 3);
  const replay = edgeland.replayLog(world.log);
  assert.equal(replay.stopped, null);
  assert.equal(replay.edits, 2);
  assert.equal(replay.landscape.stateHash, world.stateHash);
  assert.equal(replay.landscape.log, world.log);
  const report = JSON.parse(replay.report);
  assert.equal(report.edits, 2);
  assert.equal(report.state_hash, world.stateHash.toString(16).padStart(16, '0'));
  assert.equal(report.polygons, world.stats.polygons);
  replay.landscape.dispose();
}));

test('a replay stops at a bad line and keeps the edits before it', () => withWorld((world) => {
  world.startLog();
  world.carve(square(100, 100, 50));
  // A closed ring: the line fails for its material, not for its WKT.
  const bad = edgeland.replayLog(world.log + 'fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))\n');
  assert.ok(bad.stopped instanceof edgeland.LoadError && bad.stopped.index === 3);
  assert.match(bad.stopped.message, /material '300'/);
  assert.equal(bad.edits, 1);
  assert.equal(bad.landscape.stateHash, world.stateHash);
  assert.equal(JSON.parse(bad.report).stopped_at_line, 3);
  bad.landscape.dispose();
  const none = edgeland.replayLog('carve POLYGON((0 0,1 0,1 1,0 1))\n');
  assert.equal(none.landscape, null);
  assert.equal(none.stopped.index, 1);
  assert.deepEqual(Object.keys(JSON.parse(none.report)), ['edits', 'stopped_at_line', 'error']);
}));
