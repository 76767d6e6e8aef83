// The game layer from JavaScript: chains and islands in step with edits, detach, meshes, pieces.
import assert from 'node:assert/strict';
import {test} from 'node:test';

import * as edgeland from '../index.js';
import {IslandTracker, Landscape, SurfaceTracker} from '../index.js';

const square = (x, y, side) => [[[x, y], [x + side, y], [x + side, y + side], [x, y + side]]];

test('trackers follow edits, and detach takes an island out', () => {
  const world = new Landscape([[0, 0], [1024, 512]]);
  const surface = new SurfaceTracker(world), islands = new IslandTracker(world);
  let changes = world.fill(square(0, 0, 100), 1);  // on the border: held
  const ground = surface.update(world, changes);
  assert.ok(ground.chains.length >= 1 && !ground.chains[0].closed && ground.materials[0] === 1);
  assert.equal(islands.update(world, changes).length, 0);

  changes = world.fill(square(400, 300, 40), 2);  // floating
  const floating = surface.update(world, changes);
  assert.equal(floating.chains.length, 1);
  assert.ok(floating.chains[0].closed);
  assert.equal(edgeland.meshUpdate(changes).meshes[0].triangles.length, 6);
  const found = islands.update(world, changes);
  assert.equal(found.length, 1);
  assert.equal(found.islands[0].twiceArea, 3200n);
  assert.equal(found.islands[0].pieces[0].material, 2);

  const d = edgeland.detach(world, found, 0);
  assert.equal(d.twiceArea, 3200n);
  assert.equal(d.centroid.x, 420n * d.centroid.den);
  assert.equal(d.regions.count, 1);
  assert.equal(world.materialAt([420, 320]), 0);
  assert.deepEqual([...surface.update(world, d.changes).removed], [floating.chains[0].id]);
  assert.equal(islands.update(world, d.changes).length, 0);
  d.dispose();
  assert.throws(() => edgeland.detach(world, found, 0), edgeland.StaleIsland);
  assert.throws(() => edgeland.detach(world, found, 1), edgeland.IndexOutOfRange);
  assert.equal(edgeland.allMeshes(world).length, world.polygonsIn().count);
  for (const object of [found, surface, islands, world]) object.dispose();
});

test('material tables, walls and convex pieces', () => {
  const world = new Landscape([[0, 0], [256, 256]]);
  world.fill(square(100, 100, 20), 3);
  assert.equal(new IslandTracker(world).islands(world).length, 1);
  assert.equal(new IslandTracker(world, {anchored: [3]}).islands(world).length, 0);
  assert.equal(new SurfaceTracker(world, {solid: [1]}).chains.chains.length, 0);
  const walls = new SurfaceTracker(world, {borderWall: true}).chains;
  assert.ok(walls.chains.length > 1);
  const ell = [[0, 0], [20, 0], [20, 10], [10, 10], [10, 20], [0, 20]];
  assert.equal(edgeland.convexPieces(ell).length, 2);
  assert.throws(() => edgeland.convexPieces(ell, 2), (e) => e instanceof edgeland.InvalidArgument && e.minimum === 3);
});
