// The game driver from JavaScript: a frame's edits in, chains (with ghosts), meshes and debris
// out; buried bodies; reset to a snapshot; typed errors that leave the driver as it was.
import assert from 'node:assert/strict';
import {test} from 'node:test';

import * as edgeland from '../index.js';
import {Edit, GameDriver, Landscape, Shape} from '../index.js';

// An empty world of 8 x 8 cells, so the ground's surface crosses cell lines.
const cellWorld = (limits = {}) =>
  new Landscape([[0, 0], [1024, 512]], 0, {gridDepth: 3, checked: true, ...limits});
const box = (x0, y0, x1, y1) => Shape.box([x0, y0], [x1, y1]);

// The chains of a {chains, offsets, xy} result as records with their points.
function chainsOf(c) {
  return c.chains.map((info, i) => {
    const points = [];
    for (let k = c.offsets[i]; k < c.offsets[i + 1]; ++k) points.push([c.xy[2 * k], c.xy[2 * k + 1]]);
    return {...info, points};
  });
}

// The chains a game holds, kept from the updates alone.
class ChainMirror {
  constructor() { this.chains = new Map(); }
  apply(update) {
    for (const id of update.removed) assert.ok(this.chains.delete(id), `chain ${id} removed unheld`);
    for (const c of chainsOf(update)) this.chains.set(c.id, c);
  }
  matches(game) {
    const now = chainsOf(game.chains);
    assert.equal(now.length, this.chains.size);
    for (const c of now) assert.deepEqual(this.chains.get(c.id), c);
  }
}

test('a frame gives chains, meshes and debris', () => {
  const world = cellWorld();
  const game = new GameDriver(world);
  const mirror = new ChainMirror();
  const u = game.apply([Edit.fill(box(0, 0, 1024, 100), 1),      // ground, held by the border
    Edit.fill(box(400, 300, 440, 340), 2)]);                      // a rock in the air
  mirror.apply(u.chains);
  mirror.matches(game);
  assert.equal(u.debris.length, 1);
  const rock = u.debris[0];
  assert.equal(rock.twiceArea, 3200n);
  assert.equal(rock.centroid.x, 420n * rock.centroid.den);
  assert.equal(rock.centroid.y, 320n * rock.centroid.den);
  assert.deepEqual(rock.bounds, [[400, 300], [440, 340]]);
  assert.deepEqual(rock.regions.map((r) => r.material), [2]);
  assert.equal(rock.pieces.length, 1);
  assert.equal(rock.pieces[0].points.length, 4);
  assert.equal(rock.meshes.length, 1);
  assert.equal(rock.meshes[0].triangles.length, 6);
  assert.deepEqual(u.meshes.meshes.map((m) => m.id).sort(), [...u.changes.added.ids].sort());
  assert.equal(u.work.islandsDetached, 1);
  u.dispose();

  // Where one chain ends at a cell line the next begins, each one's ghost the other's point.
  const open = chainsOf(game.chains).filter((c) => !c.closed);
  let joints = 0;
  for (const a of open) {
    for (const b of open) {
      if (a === b || String(a.points.at(-1)) !== String(b.points[0])) continue;
      assert.deepEqual(a.ghostNext, b.points[1]);
      assert.deepEqual(b.ghostPrev, a.points.at(-2));
      ++joints;
    }
  }
  assert.equal(joints, 7);  // the ground's top crosses 7 cell lines
  const now = game.landscape;
  assert.equal(now.materialAt([420, 320]), 0);
  assert.equal(world.materialAt([10, 10]), 0);  // the caller's world is its own

  mirror.apply(game.apply([Edit.fill(box(600, 60, 650, 250), 3)]).chains);
  assert.ok(game.buried([[610, 210], [620, 220]]));
  assert.ok(!game.buried([[100, 400], [110, 410]]));

  mirror.apply(game.apply([Edit.carve(Shape.circle([300, 100], 60))]).chains);
  assert.notEqual(game.landscape.stateHash, now.stateHash);
  mirror.matches(game);
  const back = game.reset(now);
  mirror.apply(back.chains);
  assert.equal(game.landscape.stateHash, now.stateHash);
  mirror.matches(game);
  assert.ok(back.changes.removed.length > 0);
  for (const object of [back, now, game, world]) object.dispose();
});

test('edits of every kind; typed errors change nothing', () => {
  const game = new GameDriver(new Landscape([[0, 0], [256, 256]], 1));
  const square = [[[100, 100], [150, 100], [150, 150], [100, 150]]];
  game.apply([Edit.carve(square), Edit.fillEmpty(square, 2), Edit.replace(square, 2, 3),
    Edit.relabel(square, new Map([[3, 4], [1, 5]]))]).dispose();
  assert.equal(game.landscape.materialAt([120, 120]), 4);
  assert.equal(game.apply().debris.length, 0);  // no edits: only the debris queue moves

  assert.throws(() => new GameDriver(cellWorld(), {maxPieceVertices: 2}),
    (e) => e instanceof edgeland.InvalidArgument && e.value === 2 && e.minimum === 3);
  const limited = new GameDriver(cellWorld({maxShapeVertices: 16}));
  const hash = limited.landscape.stateHash, chains = chainsOf(limited.chains);
  assert.throws(() => limited.apply([Edit.carve(box(10, 10, 50, 50)), Edit.fill(box(10, 10, 50, 50), 300)]),
    (e) => e instanceof edgeland.InvalidMaterial && e.value === 300);
  assert.throws(() => limited.apply([Edit.carve(box(10, 10, 50, 50)),
    Edit.fill(Shape.circle([500, 300], 100), 1)]),
  (e) => e instanceof edgeland.LimitExceeded && e.limit === 16);
  assert.equal(limited.landscape.stateHash, hash);
  assert.deepEqual(chainsOf(limited.chains), chains);
  assert.throws(() => new GameDriver(cellWorld(), {speed: 3}), TypeError);
});

test('options: triangle pieces, no meshes, no debris, anchored', () => {
  const world = cellWorld();
  const rock = () => [Edit.fill(box(400, 300, 440, 340), 4)];
  const u = new GameDriver(world, {maxPieceVertices: 3, meshes: false}).apply(rock());
  assert.equal(u.debris[0].pieces.length, 2);
  assert.equal(u.debris[0].meshes.length, 0);
  assert.equal(u.meshes.meshes.length, 0);
  assert.equal(new GameDriver(world, {debris: false}).apply(rock()).debris.length, 0);
  assert.equal(new GameDriver(world, {anchored: [4]}).apply(rock()).debris.length, 0);
  const walls = new GameDriver(world, {borderWall: true}).chains;
  assert.ok(walls.chains.length > 0 && walls.materials.includes(0));
});
