// The TypeScript declarations (index.d.ts) against typical use: `tsc --noEmit --strict` must
// accept this file (ctest bindings.js_types).
import {CoordinateOutOfRange, Edit, EdgelandError, GameDriver, Landscape, Shape, type ChangeSet,
  type Crossing, type Debris, type GameUpdate} from '../index.js';

const world = new Landscape([[0, 0], [1024, 512]], 1, {tree: 'kd', checked: true});
const changes: ChangeSet = world.carve(Shape.circle([512, 256], 100));
const removed: bigint[] = [...changes.removed];
const area: bigint | undefined = changes.areaDelta.get(1);
for (const p of changes.added) {
  const first: [number, number] = p.points[0];
  console.log(p.id + 1n, p.material, first, p.cell[1][0]);
}
const hit: Crossing | null = world.raycast([512, 256], [1000, 256]);
if (hit !== null) console.log(Number(hit.point.x) / Number(hit.point.den), hit.after);
try {
  world.fill([[[0, 0], [3000000000, 0], [0, 10]]], 2);
} catch (e) {
  if (e instanceof CoordinateOutOfRange) console.log(e.rule, e.vertex, e.where[0]);
  else if (e instanceof EdgelandError) console.log(e.status);
}
const hash: bigint = world.stateHash;
const copy: Landscape = Landscape.load(world.save());
world.checked = false;
console.log(removed.length, area, hash === copy.stateHash, world.polygonsIn([[0, 0], [10, 10]]).xy);
const game = new GameDriver(world, {maxPieceVertices: 6, anchored: [1], debrisBudget: 1024n});
const update: GameUpdate = game.apply([Edit.fill(Shape.circle([512, 256], 20), 2),
  Edit.relabel([[[0, 0], [10, 0], [0, 10]]], [[1, 3]])]);
for (const id of update.chains.removed) console.log(id + 1n);
const fell: Debris[] = update.debris;
if (fell.length > 0) console.log(fell[0].pieces[0].points[0][0], fell[0].centroid.den);
console.log(game.buried([[500, 250], [510, 260]]), update.work.cellsScanned, game.debrisWaiting);
update.dispose();
game.dispose();
copy.dispose();
world.dispose();
