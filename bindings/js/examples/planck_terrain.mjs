// A game's own physics driving edgeland: planck.js (a JavaScript port of Box2D) on the game
// driver's updates. The terrain is one chain fixture per surface chain (with its ghost vertices,
// so bodies slide over the joints), replaced per update only where chains changed; debris becomes
// dynamic bodies of its convex pieces. A ball rests on the ground; a blast opens a crater under
// it and it falls in; a rock filled in the air breaks off as debris and lands on the ground.
// Run: node examples/planck_terrain.mjs (after npm ci). ctest bindings.js_planck_example checks
// its last line.
import * as planck from 'planck';

import {Edit, GameDriver, Landscape, Shape} from '../index.js';

const UNITS_PER_METRE = 32;
const metres = ([x, y]) => planck.Vec2(x / UNITS_PER_METRE, y / UNITS_PER_METRE);
const physics = new planck.World({gravity: planck.Vec2(0, -10)});
const game = new GameDriver(new Landscape([[0, 0], [2048, 1024]], 0));

// The terrain: a static body per chain, by chain id.
const terrain = new Map();
function addChain(chains, i) {
  const info = chains.chains[i], points = [];
  for (let k = chains.offsets[i]; k < chains.offsets[i + 1]; ++k) {
    points.push(metres([chains.xy[2 * k], chains.xy[2 * k + 1]]));
  }
  const shape = planck.Chain(points, info.closed);
  if (!info.closed) {
    shape.setPrevVertex(metres(info.ghostPrev));
    shape.setNextVertex(metres(info.ghostNext));
  }
  const body = physics.createBody();
  body.createFixture(shape, {friction: 0.6});
  terrain.set(info.id, body);
}

// Debris: a dynamic body at the island's centroid, a polygon fixture per convex piece.
const rocks = [];
function addDebris(d) {
  const c = [Number(d.centroid.x) / Number(d.centroid.den), Number(d.centroid.y) / Number(d.centroid.den)];
  const body = physics.createBody({type: 'dynamic', position: metres(c)});
  for (const piece of d.pieces) {
    body.createFixture(planck.Polygon(piece.points.map(([x, y]) => metres([x - c[0], y - c[1]]))),
      {density: 1, friction: 0.6});
  }
  rocks.push(body);
}

// One frame: the edits in, the update applied between two steps.
function frame(edits) {
  const u = game.apply(edits);
  for (const id of u.chains.removed) {
    physics.destroyBody(terrain.get(id));
    terrain.delete(id);
  }
  for (let i = 0; i < u.chains.chains.length; ++i) addChain(u.chains, i);
  for (const d of u.debris) addDebris(d);
  u.dispose();
}
const settle = (steps) => {
  for (let i = 0; i < steps; ++i) physics.step(1 / 60);
};
const units = (body) => body.getPosition().y * UNITS_PER_METRE;

frame([Edit.fill(Shape.box([0, 0], [2048, 400]), 1)]);  // ground up to y = 400
const ball = physics.createBody({type: 'dynamic', position: metres([1024, 480])});
ball.createFixture(planck.Circle(0.5), {density: 1, friction: 0.4});
settle(120);
const restingOnGround = units(ball);
frame([Edit.carve(Shape.circle([1024, 400], 120)),       // the crater
  Edit.fill(Shape.box([1500, 700], [1560, 760]), 2)]);   // a rock in the air: debris
settle(240);
const restingInCrater = units(ball), rockAt = units(rocks[0]);
// The crater's floor is at 280: the ball's centre rests about its radius (16 units) above it;
// the 60-unit rock's centre 30 units above the ground.
const now = game.landscape;
const below = now.materialAt([Math.round(ball.getPosition().x * UNITS_PER_METRE),
  Math.round(restingInCrater) - 24]);
console.log(`ball at y = ${restingOnGround.toFixed(1)} on the ground, ` +
  `${restingInCrater.toFixed(1)} in the crater (material under it: ${below}); ` +
  `the rock fell to y = ${rockAt.toFixed(1)}`);
if (!(restingOnGround > 400 && restingOnGround < 425 && restingInCrater > 280 &&
      restingInCrater < 305 && below === 1 && rocks.length === 1 && rockAt > 425 &&
      rockAt < 435 && now.materialAt([1530, 730]) === 0)) {
  throw new Error('the ball did not fall into the crater, or the rock did not land');
}
console.log(`planck example: ${terrain.size} terrain chains, the rock landed, ` +
  'the ball fell into the crater');
now.dispose();
game.dispose();
