// The page's world (play/web/README.md): the JavaScript package's game driver (bindings/js) over
// the demo world, the tools' edits, undo and redo by snapshots, edit logs out and in, and every
// change as one update for the view and the physics. Everything done with the world goes through
// the package; only the demo world's generator and the palette come from the demo module.
import createDemoModule from './demo.mjs';
import {EdgelandError, Edit, GameDriver, Landscape, Shape, replayLog} from './edgeland/index.js';

export const demo = await createDemoModule();

// play/core/tool_shapes.hpp's rule, which the desktop front end follows: a click is the regular
// 24-gon around the point, a drag the capsule around the stroke, the radius clamped.
const kToolCorners = 24;
const kMinToolRadius = 2, kMaxToolRadius = 1 << 20;
const kMaxUndo = 256;  // play/core/session.hpp's default

function toolShape(from, to, radius) {
  const r = Math.min(kMaxToolRadius, Math.max(kMinToolRadius, radius));
  if (from[0] === to[0] && from[1] === to[1]) return Shape.regularPolygon(to, r, kToolCorners);
  return Shape.capsule(from, to, r);
}

// The edit each tool makes (`material`: the one it puts down; `from`: the one replace takes).
const kToolEdits = {
  explosion: (shape) => Edit.carve(shape),
  digger: (shape) => Edit.carve(shape),
  fill: (shape, material) => Edit.fill(shape, material),
  water: (shape, material) => Edit.fillEmpty(shape, material),
  replace: (shape, material, from) => Edit.replace(shape, from, material),
};
export const kTools = Object.keys(kToolEdits);

// Water is no obstacle; the world's border is a wall, so that nothing rolls out of the world;
// the page draws polygons, so no meshes.
function gameOptions() {
  const solid = [];
  for (let m = 1; m < 256; ++m) if (m !== demo.water()) solid.push(m);
  return {solid, borderWall: true, meshes: false};
}

// A new world over the box recording its log: the demo world of `seed` (> 0), each ring of the
// generator imported (OGC) and applied as demo::LandscapeEditor does natively, a ring of no
// area skipped; or the box filled with `fill` (seed 0).
export function startingWorld(box, fill, seed) {
  const world = new Landscape(box, seed > 0 ? 0 : fill);
  world.startLog();
  if (seed === 0) return world;
  const [[x0, y0], [x1, y1]] = box;
  for (const {kind, material, from, ring} of demo.worldEdits(x0, y0, x1, y1, seed)) {
    const shape = Shape.import([[ring]]);
    try {
      if (shape.polygons.length === 0) continue;
      if (kind === 'replace') world.replace(shape, from, material).dispose();
      else world[kind](shape, material).dispose();
    } finally {
      shape.dispose();
    }
  }
  return world;
}

// What changed, for the view and the physics (everything dropped first when `reset`): polygon
// ids `removed` and Polygons `added`, the cells the edit made, the chains to drop and add (the
// package's chains: solid on the left, with ghost vertices), the debris that broke off, the
// world box; `error` for a refused edit, which changed nothing.
const noChange = (box) => ({reset: false, removed: new BigUint64Array(0), added: null,
  cells: new Int32Array(0), chains: {removed: new BigUint64Array(0), chains: []}, debris: [],
  box});

// Reads the game driver's update into the page's, then frees it.
function fromDriver(u, box) {
  try {
    return {reset: false, removed: u.changes.removed, added: u.changes.added,
      cells: u.changes.cells, chains: u.chains, debris: u.debris, box};
  } finally {
    u.dispose();
  }
}

export class PlaygroundWorld {
  // The demo world (seed > 0) or a world filled with `fill` (seed 0) over [[x0, y0], [x1, y1]].
  constructor(box, fill, seed) {
    const world = startingWorld(box, fill, seed);
    this.game = new GameDriver(world, gameOptions());
    world.dispose();
    this.undoStack = [];
    this.redoStack = [];
    Object.assign(this, {edits: 0, islandsDetached: 0, chains: 0, lastEditMs: 0, totalEditMs: 0});
    this.game.apply().dispose();  // the islands the world starts with fall; the page starts from everything()
  }

  // A snapshot of the world (O(1)) for fn; disposed after.
  peek(fn) {
    const world = this.game.landscape;
    try {
      return fn(world);
    } finally {
      world.dispose();
    }
  }

  get box() { return this.peek((w) => w.world); }

  // One tool edit (kTools, integer world coordinates); a refused one changes nothing.
  apply(tool, from, to, radius, material, fromMaterial) {
    const start = performance.now();
    try {
      return this.edit(tool, from, to, radius, material, fromMaterial);
    } catch (e) {
      if (!(e instanceof EdgelandError)) throw e;
      return Object.assign(noChange(null), {error: e.message});
    } finally {
      this.lastEditMs = performance.now() - start;
      this.totalEditMs += this.lastEditMs;
    }
  }

  edit(tool, from, to, radius, material, fromMaterial) {
    const shape = toolShape(from, to, radius);
    const before = this.game.landscape;
    let update;
    try {
      update = fromDriver(this.game.apply([kToolEdits[tool](shape, material, fromMaterial)]), null);
    } catch (e) {
      before.dispose();
      throw e;
    } finally {
      shape.dispose();
    }
    this.remember(this.undoStack, before);
    for (const w of this.redoStack.splice(0)) w.dispose();
    this.edits += 1;
    this.islandsDetached += update.debris.length;
    this.chains += update.chains.chains.length - update.chains.removed.length;
    return update;
  }

  remember(stack, world) {
    stack.push(world);
    if (stack.length > kMaxUndo) stack.shift().dispose();
  }

  undo() { return this.swap(this.undoStack, this.redoStack); }
  redo() { return this.swap(this.redoStack, this.undoStack); }

  // Back (or forward) to a snapshot: the driver reset to it. The islands it holds fall again.
  swap(from, to) {
    if (from.length === 0) return noChange(null);
    this.remember(to, this.game.landscape);
    const target = from.pop();
    try {
      return this.worldSwapped(this.game.reset(target));
    } finally {
      target.dispose();
    }
  }

  // After a reset the page redraws everything and adds the reset's debris.
  worldSwapped(u) {
    const update = this.everything();
    update.debris = fromDriver(u, null).debris;
    this.islandsDetached += update.debris.length;
    return update;
  }

  // Everything, as a reset (the page's first draw).
  everything() {
    const chains = this.game.chains;
    this.chains = chains.chains.length;
    return this.peek((w) => ({reset: true, removed: new BigUint64Array(0), added: w.polygonsIn(),
      cells: new Int32Array(0), chains, debris: [], box: w.world}));
  }

  // The world a landscape log describes (up to its first bad line), as `edgeland replay` builds
  // it, replaces this one (its history starts again); the update redraws it (null when the log
  // has no world). `report`: the JSON text `edgeland replay` prints for the log.
  replay(text) {
    const {landscape, report} = replayLog(text);
    if (!landscape) return {report, update: null};
    for (const w of [...this.undoStack.splice(0), ...this.redoStack.splice(0)]) w.dispose();
    this.edits = 0;
    try {
      return {report, update: this.worldSwapped(this.game.reset(landscape))};
    } finally {
      landscape.dispose();
    }
  }

  // Every cell's box, x0, y0, x1, y1 each (the cell-lines overlay).
  cells() { return this.peek((w) => w.cellsIn()); }

  log() { return this.peek((w) => w.log); }
  stateHash() { return this.peek((w) => w.stateHash.toString(16).padStart(16, '0')); }

  stats() {
    const {polygons, vertices, cells, depth} = this.peek((w) => w.stats);
    return {polygons, vertices, cells, depth, edits: this.edits, chains: this.chains,
      islandsDetached: this.islandsDetached, lastEditMs: this.lastEditMs,
      totalEditMs: this.totalEditMs};
  }
}
