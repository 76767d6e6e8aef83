// The playground page: the world of the JavaScript package (world.mjs over bindings/js), its
// tools under the mouse, undo/redo, physics (physics.js), the overlay, the share of the edit log,
// and window.playground, the page's API for scripts and tests (play/web/README.md).
'use strict';

const kWorld = {x0: 0, y0: 0, x1: 4096, y1: 2048};
const kSeed = 1;                  // the `edgeland demo` world generator's seed
const kUnitsPerMetre = 32;        // engine scale: the world is 128 m x 64 m

const playground = window.playground = {errors: []};
window.addEventListener('error', e => playground.errors.push(String(e.message)));
window.addEventListener('unhandledrejection', e => playground.errors.push(String(e.reason)));

// The package and the demo module are ES modules; this page's scripts are classic ones, so
// window.playground exists (with its `ready` promise) as soon as the page has loaded.
playground.ready = import('./world.mjs').then(({PlaygroundWorld, demo, kTools}) => {
  const kWater = demo.water();
  const colours = new Map();
  const colour = m => {
    if (!colours.has(m)) colours.set(m, '#' + demo.materialColour(m).toString(16).padStart(6, '0'));
    return colours.get(m);
  };
  const canvas = document.getElementById('view');
  const context = canvas.getContext('2d');
  const world = new PlaygroundWorld([[kWorld.x0, kWorld.y0], [kWorld.x1, kWorld.y1]], 0, kSeed);
  let box = null, view, physics;
  // The view and the physics follow the world's box (a replayed log brings its own world).
  function fitWorld(b) {
    if (box && b[0][0] === box.x0 && b[0][1] === box.y0 && b[1][0] === box.x1 && b[1][1] === box.y1) return;
    box = {x0: b[0][0], y0: b[0][1], x1: b[1][0], y1: b[1][1]};
    view = new TerrainView(box, canvas.width, canvas.height, colour);
    physics = new Physics(box, kUnitsPerMetre * (box.x1 - box.x0) / (kWorld.x1 - kWorld.x0));
  }
  fitWorld(world.box);
  const frames = {count: 0, totalMs: 0, maxMs: 0, lastMs: 0};
  let dirtyCells = new Int32Array(0);
  let lastUpdate = {removed: 0, added: 0, ms: 0};
  const timing = playground.timing = {viewMs: 0, collidersMs: 0};

  // Every change of the world goes through here: the view, the colliders, the overlay.
  function take(update) {
    if (update.error) {
      playground.refused = (playground.refused || 0) + 1;
      return update;
    }
    if (update.reset) fitWorld(update.box);
    const start = performance.now();
    view.apply(update);
    const drawn = performance.now();
    physics.apply(update);
    timing.viewMs += drawn - start;
    timing.collidersMs += performance.now() - drawn;
    dirtyCells = update.cells;
    lastUpdate = {removed: update.removed.length, added: update.added ? update.added.count : 0,
                  ms: performance.now() - start};
    return update;
  }

  // --- the API -------------------------------------------------------------------------------
  // apply(tool, fromX, fromY, toX, toY, radius, material, fromMaterial): one tool edit in world
  // coordinates (rounded to integers), the tool by name or number (kTools' order); returns
  // {removed, added, error}.
  playground.apply = (tool, fx, fy, tx, ty, radius, material = 0, from = 0) => {
    const name = typeof tool === 'number' ? kTools[tool] : tool;
    const u = take(world.apply(name, [Math.round(fx), Math.round(fy)],
                               [Math.round(tx), Math.round(ty)], Math.round(radius), material, from));
    return {removed: u.removed.length, added: u.added ? u.added.count : 0, error: u.error};
  };
  playground.explode = (x, y, r) => playground.apply('explosion', x, y, x, y, r);
  playground.dig = (x0, y0, x1, y1, r) => playground.apply('digger', x0, y0, x1, y1, r);
  playground.fill = (m, x, y, r) => playground.apply('fill', x, y, x, y, r, m);
  playground.water = (x, y, r) => playground.apply('water', x, y, x, y, r, kWater);
  playground.replace = (from, to, x, y, r) => playground.apply('replace', x, y, x, y, r, to, from);
  playground.undo = () => take(world.undo()).reset;
  playground.redo = () => take(world.redo()).reset;
  playground.log = () => world.log();
  playground.stateHash = () => world.stateHash();
  playground.stats = () => Object.assign(world.stats(), {bodies: physics.dynamic.length,
                                                         terrainFixtures: physics.terrain.size});
  // replay(logText): replays a landscape edit log into the page's world (the page then shows
  // it) and returns the object `edgeland replay LOG` prints for it.
  playground.replay = text => {
    const {report, update} = world.replay(text);
    if (update) take(update);
    return JSON.parse(report);
  };
  playground.dropBall = (x, y, r = bodySize()) => physics.dropBall(x, y, r);
  playground.dropBox = (x, y, h = bodySize() * 0.8) => physics.dropBox(x, y, h);
  playground.bodyCentres = () => physics.centres();
  playground.frameStats = () => ({frames: frames.count, meanMs: frames.totalMs / Math.max(1, frames.count),
                                  maxMs: frames.maxMs, lastMs: frames.lastMs});
  // Runs n frames at once (physics step and drawing), as the animation loop does.
  playground.runFrames = n => { for (let k = 0; k < n; ++k) frame(); return playground.frameStats(); };

  // --- frames ----------------------------------------------------------------------------------
  function frame() {
    const start = performance.now();
    physics.step(1 / 60);
    view.draw(context);
    if (document.getElementById('cells').checked) view.drawBoxes(context, world.cells(), 'rgba(255,255,255,0.3)');
    if (document.getElementById('dirty').checked) view.drawBoxes(context, dirtyCells, '#ffe14d');
    physics.draw(context, view);
    const ms = performance.now() - start;
    frames.count += 1;
    frames.totalMs += ms;
    frames.maxMs = Math.max(frames.maxMs, ms);
    frames.lastMs = ms;
    if (frames.count % 10 === 1) showOverlay();
  }

  function showOverlay() {
    const s = playground.stats();
    document.getElementById('overlay').textContent =
        `frame ${frames.lastMs.toFixed(2)} ms   edit ${s.lastEditMs.toFixed(2)} ms   ` +
        `update ${lastUpdate.ms.toFixed(2)} ms (-${lastUpdate.removed} +${lastUpdate.added})\n` +
        `polygons ${s.polygons}   vertices ${s.vertices}   cells ${s.cells}   ` +
        `chains ${s.chains}   bodies ${s.bodies}   islands ${s.islandsDetached}   edits ${s.edits}   ` +
        `hash ${world.stateHash()}`;
  }

  function loop() { frame(); requestAnimationFrame(loop); }

  // --- the mouse and the keys ------------------------------------------------------------------
  const control = id => document.getElementById(id);
  const kMaterialNames = demo.materialNames();
  for (let m = 1; m < kMaterialNames.length; ++m) {
    control('material').add(new Option(`${m} ${kMaterialNames[m]}`, m, m === 3, m === 3));
    control('from').add(new Option(`${m} ${kMaterialNames[m]} →`, m, m === 2, m === 2));
  }
  const selected = () => document.querySelector('input[name=tool]:checked').value;
  const radius = () => Math.max(4, Number(control('radius').value) || 64);
  const at = e => {
    const r = canvas.getBoundingClientRect();
    return {x: view.worldX(e.clientX - r.left), y: view.worldY(e.clientY - r.top)};
  };
  let stroke = null;  // the last point of a drag
  const bodySize = () => 24 * (box.x1 - box.x0) / (kWorld.x1 - kWorld.x0);  // 6 pixels

  function use(from, to) {
    const tool = selected();
    if (tool === 'ball') return physics.dropBall(to.x, to.y, bodySize());
    if (tool === 'box') return physics.dropBox(to.x, to.y, bodySize() * 0.8);
    const material = tool === 'water' ? kWater : Number(control('material').value);
    playground.apply(tool, from.x, from.y, to.x, to.y, radius(), material, Number(control('from').value));
  }
  canvas.addEventListener('mousedown', e => { const p = at(e); stroke = p; use(p, p); });
  canvas.addEventListener('mousemove', e => {
    if (!stroke || selected() === 'explosion' || selected() === 'ball' || selected() === 'box') return;
    const p = at(e);
    if (Math.hypot(p.x - stroke.x, p.y - stroke.y) < radius() / 2) return;
    use(stroke, p);
    stroke = p;
  });
  window.addEventListener('mouseup', () => { stroke = null; });
  canvas.addEventListener('wheel', e => {
    e.preventDefault();
    control('radius').value = Math.min(512, Math.max(4, radius() * (e.deltaY < 0 ? 1.15 : 1 / 1.15)) | 0);
  }, {passive: false});
  window.addEventListener('keydown', e => {
    if (!e.ctrlKey) return;
    if (e.key === 'z') { e.preventDefault(); playground.undo(); }
    if (e.key === 'y') { e.preventDefault(); playground.redo(); }
  });
  control('undo').onclick = () => playground.undo();
  control('redo').onclick = () => playground.redo();
  control('rain').onclick = () => {
    for (let k = 0; k < 20; ++k) {
      const x = box.x0 + (k + 0.5) * (box.x1 - box.x0) / 20, y = box.y1 - (box.y1 - box.y0) / 32;
      if (k % 2) physics.dropBall(x, y, bodySize()); else physics.dropBox(x, y, bodySize() * 0.8);
    }
  };
  control('share-log').onclick = () => {
    control('log-text').value = world.log();
    control('share-note').textContent = `${world.stats().edits} edits, state hash ${world.stateHash()}`;
  };
  control('load-log').onclick = () => {
    const json = playground.replay(control('log-text').value);
    control('share-note').textContent = json.error ? `stopped: ${json.error}` : `state hash ${json.state_hash}`;
  };

  take(world.everything());
  requestAnimationFrame(loop);
  return playground;
});
