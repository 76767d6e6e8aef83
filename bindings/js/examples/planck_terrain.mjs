// A game's own physics driving edgeland: planck.js (a JavaScript port of Box2D) bodies on the
// landscape's polygons, the terrain's fixtures replaced from each edit's change set only. A ball
// rests on the ground; a blast opens a crater under it; it falls into the crater and comes to
// rest on its floor. Run: node examples/planck_terrain.mjs (after npm ci). ctest
// bindings.js_planck_example checks its last line.
import * as planck from 'planck';

import {Landscape, Shape} from '../index.js';

const UNITS_PER_METRE = 32;
const world = new Landscape([[0, 0], [2048, 1024]], 0);
world.fill(Shape.box([0, 0], [2048, 400]), 1);  // ground up to y = 400

// The terrain: one static body per landscape polygon (a loop of its edges), keyed by id.
const physics = new planck.World({gravity: planck.Vec2(0, -10)});
const terrain = new Map();
const metres = ([x, y]) => planck.Vec2(x / UNITS_PER_METRE, y / UNITS_PER_METRE);
function addPolygon(p) {
  const body = physics.createBody();
  body.createFixture(planck.Chain(p.points.map(metres), true), {friction: 0.6});
  terrain.set(p.id, body);
}
function applyChanges(changes) {
  for (const id of changes.removed) {
    physics.destroyBody(terrain.get(id));
    terrain.delete(id);
  }
  for (const p of changes.added) addPolygon(p);
}
for (const p of world.polygonsIn()) addPolygon(p);

const ball = physics.createBody({type: 'dynamic', position: metres([1024, 480])});
ball.createFixture(planck.Circle(0.5), {density: 1, friction: 0.4});
const settle = (frames) => {
  for (let i = 0; i < frames; ++i) physics.step(1 / 60);
};

settle(120);
const restingOnGround = ball.getPosition().y * UNITS_PER_METRE;
applyChanges(world.carve(Shape.circle([1024, 400], 120)));  // the crater
settle(240);
const restingInCrater = ball.getPosition().y * UNITS_PER_METRE;
// The crater's floor is at 280: the ball's centre rests about its radius (16 units) above it.
const below = world.materialAt([Math.round(ball.getPosition().x * UNITS_PER_METRE),
  Math.round(restingInCrater) - 24]);
console.log(`ball at y = ${restingOnGround.toFixed(1)} on the ground, ` +
  `${restingInCrater.toFixed(1)} in the crater (material under it: ${below})`);
if (!(restingOnGround > 400 && restingOnGround < 425 && restingInCrater > 280 &&
      restingInCrater < 305 && below === 1)) {
  throw new Error('the ball did not fall into the crater');
}
console.log(`planck example: ${terrain.size} terrain bodies, the ball fell into the crater`);
world.dispose();
