// edgeland for JavaScript: the C API (capi/include/edgeland/edgeland.h) built to WebAssembly,
// with JavaScript names, classes and exceptions (bindings/js/README.md). An ES module for
// browsers and Node: `import { Landscape, Shape } from 'edgeland'`.
//
// Objects own WebAssembly memory: call dispose() when done (a FinalizationRegistry frees what
// is forgotten, some time after it is collected). Exact values: coordinates are numbers (every
// coordinate within the bound 2^31 - 1 is exact), ids, hashes and 128-bit values BigInts.
import createEdgelandModule from './edgeland_c.mjs';

const M = await createEdgelandModule();

const VERSION = 0x010000;  // the EL_VERSION this package was written for
if (M._el_check_version(VERSION) !== 0) {
  throw new Error(`edgeland_c ${M._el_version().toString(16)} does not serve this package (1.0)`);
}

// --- memory ---------------------------------------------------------------------------------
const heap = () => M.HEAPU8.buffer;  // views are made on use: memory may grow
const view = (Type, pointer, count) => new Type(heap(), pointer, count);
const dv = () => new DataView(heap());

// Scratch memory for one call: fn(allocate) with allocate(bytes) -> pointer, all freed after.
function scratch(fn) {
  const blocks = [];
  const allocate = (bytes) => {
    const p = M._malloc(Math.max(8, bytes));
    if (p === 0) throw new EdgelandError(2, {message: 'out of memory'});
    blocks.push(p);
    return p;
  };
  try {
    return fn(allocate);
  } finally {
    for (const p of blocks) M._free(p);
  }
}

const writePoint = (p, [x, y]) => {
  const d = dv();
  d.setBigInt64(p, BigInt(x), true);
  d.setBigInt64(p + 8, BigInt(y), true);
};
const point = (allocate, xy) => {
  const p = allocate(16);
  writePoint(p, xy);
  return p;
};
const box = (allocate, [lo, hi]) => {
  const p = allocate(32);
  writePoint(p, lo);
  writePoint(p + 16, hi);
  return p;
};
const readInt128 = (p) => {
  const d = dv();
  return (d.getBigInt64(p + 8, true) << 64n) | d.getBigUint64(p, true);
};

// --- errors ---------------------------------------------------------------------------------
const NONE = (1n << 64n) - 1n;
const STATUS_NAMES = {
  1: 'NullArgument', 2: 'OutOfMemory', 3: 'VersionMismatch', 4: 'InternalError',
  10: 'InvalidInput', 11: 'CoordinateOutOfRange', 12: 'InvalidBox', 13: 'TooManyVertices',
  14: 'InvalidArgument', 15: 'ArgumentOutOfRange', 16: 'NonPositiveArea', 17: 'InvalidOverlay',
  20: 'InvalidConfig', 21: 'InvalidMaterial', 22: 'LimitExceeded', 23: 'LoadError',
  24: 'DeltaError', 25: 'DeltaMismatch', 26: 'InvalidPath', 27: 'RegionNotLoaded',
  28: 'UnknownPolygon', 30: 'StaleIsland', 40: 'IndexOutOfRange', 41: 'BufferTooSmall',
};
export const RULES = ['too-few-vertices', 'coordinate-out-of-range', 'repeated-vertex',
  'self-intersection', 'spike', 'not-counter-clockwise', 'overlapping-interiors', 'inverted-box'];

// Every edgeland error: `status` (the el_status), `kind` (the rule, setting or limit),
// `operand`, `index`, `vertex` (null when none), `value`, `limit`, `minimum`, `where`.
export class EdgelandError extends Error {
  constructor(status, fields) {
    super(fields.message);
    this.name = STATUS_NAMES[status] ?? 'EdgelandError';
    Object.assign(this, {status, kind: 0, operand: 0, index: null, vertex: null, value: 0,
      limit: 0, minimum: 0, where: [0, 0]}, fields);
  }
}
export class InvalidInput extends EdgelandError {
  get rule() { return RULES[this.kind]; }
}
export class CoordinateOutOfRange extends InvalidInput {}
export class InvalidBox extends InvalidInput {}
export class InvalidMaterial extends EdgelandError {}
export class InvalidConfig extends EdgelandError {}
export class LimitExceeded extends EdgelandError {}
export class LoadError extends EdgelandError {}
export class DeltaError extends EdgelandError {}
export class DeltaMismatch extends EdgelandError {}
export class InvalidPath extends EdgelandError {}
export class RegionNotLoaded extends EdgelandError {}
export class UnknownPolygon extends EdgelandError {}
export class StaleIsland extends EdgelandError {}
export class IndexOutOfRange extends EdgelandError {}
export class InvalidArgument extends EdgelandError {}
export class ArgumentOutOfRange extends EdgelandError {}
const CLASSES = {10: InvalidInput, 11: CoordinateOutOfRange, 12: InvalidBox, 15: ArgumentOutOfRange,
  20: InvalidConfig, 21: InvalidMaterial, 22: LimitExceeded, 23: LoadError, 14: InvalidArgument,
  24: DeltaError, 25: DeltaMismatch, 26: InvalidPath, 27: RegionNotLoaded, 28: UnknownPolygon,
  30: StaleIsland, 40: IndexOutOfRange};

const ERROR_SIZE = 328;
function readError(p) {
  const d = dv();
  const index = d.getBigUint64(p + 16, true), vertex = d.getBigUint64(p + 24, true);
  const bytes = view(Uint8Array, p + 72, 256);
  return {
    kind: d.getUint32(p + 8, true),
    operand: d.getUint32(p + 12, true),
    index: index === NONE ? null : Number(index),
    vertex: vertex === NONE ? null : Number(vertex),
    value: Number(d.getBigInt64(p + 32, true)),
    limit: Number(d.getBigInt64(p + 40, true)),
    minimum: Number(d.getBigInt64(p + 48, true)),
    where: [Number(d.getBigInt64(p + 56, true)), Number(d.getBigInt64(p + 64, true))],
    message: new TextDecoder().decode(bytes.slice(0, bytes.indexOf(0))),
  };
}

// Calls an el_* function whose last argument is an el_error*: its error, or null on success.
function failure(allocate, fn, ...args) {
  const e = allocate(ERROR_SIZE);
  M._el_error_init(e);
  const status = fn(...args, e);
  return status === 0 ? null : new (CLASSES[status] ?? EdgelandError)(status, readError(e));
}

// The same, throwing the error.
function call(allocate, fn, ...args) {
  const error = failure(allocate, fn, ...args);
  if (error) throw error;
}

// A new handle through an out-parameter.
function made(allocate, fn, ...args) {
  const out = allocate(4);
  call(allocate, fn, ...args, out);
  return dv().getUint32(out, true);
}

// --- handles ----------------------------------------------------------------------------------
const registry = new FinalizationRegistry(({destroy, pointer}) => destroy(pointer));

class Handle {
  constructor(pointer, destroy) {
    this._pointer = pointer;
    this._destroy = destroy;
    registry.register(this, {destroy, pointer}, this);
  }
  get pointer() {
    if (!this._pointer) throw new EdgelandError(1, {message: `${this.constructor.name} disposed`});
    return this._pointer;
  }
  dispose() {
    if (!this._pointer) return;
    registry.unregister(this);
    this._destroy(this._pointer);
    this._pointer = 0;
  }
}

// The C arrays of a result handle (count from a size_t out-parameter), copied out.
function array(allocate, fn, handle, Type, perItem = 1) {
  const count = allocate(4);
  const p = fn(handle, count);
  const n = dv().getUint32(count, true) * perItem;
  return n === 0 ? new Type(0) : view(Type, p, n).slice();
}

// Polygons as flat arrays: polygon i has ids[i], materials[i], its cell's box
// cells[4i .. 4i + 3] (x0, y0, x1, y1) and the points xy[2 offsets[i] .. 2 offsets[i + 1]).
export class Polygons {
  constructor(ids, materials, cells, offsets, xy) {
    Object.assign(this, {ids, materials, cells, offsets, xy});
  }
  get count() { return this.ids.length; }
  // Polygon i as {id, material, cell: [[x0, y0], [x1, y1]], points: [[x, y], ...]}.
  polygon(i) {
    const points = [];
    for (let k = this.offsets[i]; k < this.offsets[i + 1]; ++k) {
      points.push([this.xy[2 * k], this.xy[2 * k + 1]]);
    }
    const c = this.cells;
    return {id: this.ids[i], material: this.materials[i],
      cell: [[c[4 * i], c[4 * i + 1]], [c[4 * i + 2], c[4 * i + 3]]], points};
  }
  *[Symbol.iterator]() {
    for (let i = 0; i < this.count; ++i) yield this.polygon(i);
  }
}

// int64 coordinates of the C arrays as exact numbers (every coordinate is within 2^31 - 1).
const int32s = (big) => Int32Array.from(big, Number);

function readPolygons(allocate, h) {
  return new Polygons(
    array(allocate, M._el_polygons_ids, h, BigUint64Array),
    array(allocate, M._el_polygons_materials, h, Uint8Array),
    int32s(array(allocate, M._el_polygons_cells, h, BigInt64Array, 4)),
    array(allocate, M._el_polygons_offsets, h, Uint32Array),
    int32s(array(allocate, M._el_polygons_points, h, BigInt64Array, 2)));
}

// What an edit changed: ids removed (ascending), polygons added (ascending id), the cells rebuilt
// (4 numbers each), twice the change of area per material (exact; sums to 0). It keeps the C
// change set, which the game layer's trackers and meshUpdate take: dispose() frees it at once.
export class ChangeSet extends Handle {
  constructor(pointer, destroy, owner = null) {
    super(pointer, destroy);
    this._owner = owner;  // a detached island's change set lives in its island's handle
    scratch((allocate) => {
      const deltas = new Map();
      const count = allocate(4);
      const p = M._el_changes_area_delta(pointer, count);
      for (let i = 0; i < dv().getUint32(count, true); ++i) {
        deltas.set(dv().getUint32(p + 32 * i + 24, true), readInt128(p + 32 * i));
      }
      this.removed = array(allocate, M._el_changes_removed, pointer, BigUint64Array);
      this.added = readPolygons(allocate, M._el_changes_added(pointer));
      this.cells = int32s(array(allocate, M._el_changes_cells, pointer, BigInt64Array, 4));
      this.areaDelta = deltas;
    });
  }
}

// A material change along a segment: t and the point exact ({num, den} of BigInts), the
// rounded point, the polygon entered (after != 0) or left and its edge, the outward normal.
function readCrossing(p) {
  const d = dv();
  const den = readInt128(p + 96);
  return {
    t: {num: readInt128(p), den: readInt128(p + 24)},
    point: {x: readInt128(p + 48), y: readInt128(p + 72), den},
    rounded: [Number(d.getBigInt64(p + 120, true)), Number(d.getBigInt64(p + 128, true))],
    normal: [Number(d.getBigInt64(p + 136, true)), Number(d.getBigInt64(p + 144, true))],
    polygon: d.getBigUint64(p + 152, true),
    edge: d.getUint32(p + 160, true),
    before: d.getUint8(p + 164),
    after: d.getUint8(p + 165),
  };
}

function readBytes(allocate, h) {
  try {
    const size = allocate(4);
    const p = M._el_bytes_data(h, size);
    const n = dv().getUint32(size, true);
    return n === 0 ? new Uint8Array(0) : view(Uint8Array, p, n).slice();
  } finally {
    M._el_bytes_destroy(h);
  }
}

// --- shapes -----------------------------------------------------------------------------------
// Point lists ([[x, y], ...] each) as CSR in scratch memory: xy and offsets[0 .. lists.length].
function csr(allocate, lists) {
  const n = lists.reduce((sum, list) => sum + list.length, 0);
  const xy = allocate(16 * n), offsets = allocate(4 * (lists.length + 1));
  let k = 0;
  dv().setUint32(offsets, 0, true);
  lists.forEach((list, i) => {
    for (const p of list) writePoint(xy + 16 * k++, p);
    dv().setUint32(offsets + 4 * (i + 1), k, true);
  });
  return {xy, offsets};
}

// A polygon set validated once (strictly simple, counter-clockwise, hole-free, disjoint
// interiors): new Shape([[[x, y], ...], ...]) or a builder. InvalidInput names the polygon and
// vertex of a broken rule.
export class Shape extends Handle {
  constructor(polygons, pointer = 0) {
    if (!pointer) {
      pointer = scratch((allocate) => {
        const {xy, offsets} = csr(allocate, polygons);
        return made(allocate, M._el_shape_create, xy, offsets, polygons.length);
      });
    }
    super(pointer, M._el_shape_destroy);
  }
  // Any polygons read with OGC semantics (el_shape_import): [[exterior, hole, ...], ...], each
  // ring [[x, y], ...], clockwise or self-intersecting as drawn; the shape is the valid,
  // hole-free pieces of the region they enclose (none for rings of no area).
  static import(polygons) {
    return scratch((a) => {
      const {xy, offsets} = csr(a, polygons.flat(1));
      const rings = a(4 * (polygons.length + 1));
      let r = 0;
      dv().setUint32(rings, 0, true);
      polygons.forEach((polygon, i) => dv().setUint32(rings + 4 * (i + 1), (r += polygon.length), true));
      return new Shape(null, made(a, M._el_shape_import, xy, offsets, rings, polygons.length));
    });
  }
  static circle(center, radius) {
    return scratch((a) => new Shape(null, made(a, M._el_shape_circle, point(a, center), BigInt(radius))));
  }
  static regularPolygon(center, radius, sides, [phaseNum, phaseDen] = [0, 1]) {
    return scratch((a) => new Shape(null, made(a, M._el_shape_regular_polygon, point(a, center),
      BigInt(radius), BigInt(sides), BigInt(phaseNum), BigInt(phaseDen))));
  }
  static capsule(from, to, radius) {
    return scratch((a) => new Shape(null, made(a, M._el_shape_capsule, point(a, from),
      point(a, to), BigInt(radius))));
  }
  static box(lo, hi) {
    return scratch((a) => new Shape(null, made(a, M._el_shape_box, box(a, [lo, hi]))));
  }
  static rotatedBox(center, halfWidth, halfHeight, [angleNum, angleDen] = [0, 1]) {
    return scratch((a) => new Shape(null, made(a, M._el_shape_rotated_box, point(a, center),
      BigInt(halfWidth), BigInt(halfHeight), BigInt(angleNum), BigInt(angleDen))));
  }
  // The polygons, each an array of [x, y].
  get polygons() {
    return scratch((a) => {
      const h = made(a, M._el_shape_polygons, this.pointer);
      try {
        return [...readPolygons(a, h)].map((p) => p.points);
      } finally {
        M._el_polygons_destroy(h);
      }
    });
  }
}

const asShape = (shape) => (shape instanceof Shape ? {shape, own: false}
  : {shape: new Shape(shape), own: true});

// --- landscapes -------------------------------------------------------------------------------
const CONFIG_SIZE = 56;
const CONFIG_FIELDS = {  // name: [offset, setter]
  tree: [4, 'setUint32'], edgeCap: [8, 'setUint32'], mergeBelow: [12, 'setUint32'],
  minCellSize: [16, 'setBigInt64'], gridDepth: [24, 'setInt32'], maxVertices: [32, 'setBigUint64'],
  maxShapeVertices: [40, 'setBigUint64'], maxCells: [48, 'setBigUint64'],
};
function config(allocate, options = {}) {
  const c = allocate(CONFIG_SIZE);
  M._el_landscape_config_init(c);
  const d = dv();
  for (const [name, value] of Object.entries(options)) {
    if (name === 'checked') {
      d.setUint32(c + 28, value ? 1 : 0, true);
    } else if (name === 'tree') {
      d.setUint32(c + 4, value === 'kd' ? 1 : 0, true);
    } else if (CONFIG_FIELDS[name]) {
      const [offset, setter] = CONFIG_FIELDS[name];
      d[setter](c + offset, setter.includes('Big') ? BigInt(value) : value, true);
    } else {
      throw new TypeError(`unknown landscape option ${name}`);
    }
  }
  return c;
}

// A changeable world of materials 0..255 (C++ edgeland::Landscape). new Landscape([[x0, y0],
// [x1, y1]], fill, options): options tree ('quadtree' or 'kd'), edgeCap, mergeBelow,
// minCellSize, gridDepth, checked, maxVertices, maxShapeVertices, maxCells. Edits take a Shape
// (or polygons) and return a change set; a failed edit throws and leaves the world as it was.
export class Landscape extends Handle {
  constructor(world, fill = 0, options = {}, pointer = 0) {
    if (!pointer) {
      pointer = scratch((a) => made(a, M._el_landscape_create, box(a, world), fill, config(a, options)));
    }
    super(pointer, M._el_landscape_destroy);
  }

  // A snapshot in O(1): later edits of either never show in the other.
  clone() {
    return scratch((a) => new Landscape(null, 0, {}, made(a, M._el_landscape_clone, this.pointer)));
  }
  // The versioned, checksummed binary save.
  save() {
    return scratch((a) => readBytes(a, made(a, M._el_landscape_save, this.pointer)));
  }
  // A world from save bytes (untrusted: LoadError's index is the byte offset).
  static load(bytes, limits = {}) {
    return scratch((a) => {
      const data = a(bytes.length);
      view(Uint8Array, data, bytes.length).set(bytes);
      return new Landscape(null, 0, {}, made(a, M._el_landscape_load, data, bytes.length, config(a, limits)));
    });
  }

  _edit(fn, shape, ...args) {
    const s = asShape(shape);
    try {
      return scratch((a) => new ChangeSet(made(a, fn, this.pointer, s.shape.pointer, ...args),
        M._el_changes_destroy));
    } finally {
      if (s.own) s.shape.dispose();
    }
  }
  carve(shape) { return this._edit(M._el_landscape_carve, shape); }
  fill(shape, material) { return this._edit(M._el_landscape_fill, shape, material); }
  fillEmpty(shape, material) { return this._edit(M._el_landscape_fill_empty, shape, material); }
  replace(shape, from, to) { return this._edit(M._el_landscape_replace, shape, from, to); }
  // Under the shape every material `from` of the pairs ([[from, to], ...] or a Map) becomes its
  // `to`, all at once (a later pair for one material wins).
  relabel(shape, pairs) {
    const list = [...(pairs instanceof Map ? pairs.entries() : pairs)];
    const fromTo = M._malloc(8 * Math.max(1, list.length));
    try {
      list.forEach(([from, to], i) => {
        dv().setInt32(fromTo + 8 * i, from, true);
        dv().setInt32(fromTo + 8 * i + 4, to, true);
      });
      return this._edit(M._el_landscape_relabel, shape, fromTo, list.length);
    } finally {
      M._free(fromTo);
    }
  }

  // The material at p (a point on a boundary has the material east of it).
  materialAt(p) {
    return scratch((a) => {
      const m = a(1);
      call(a, M._el_landscape_material_at, this.pointer, point(a, p), m);
      return M.HEAPU8[m];
    });
  }
  // Every material change along the segment, in order, exact.
  crossings(from, to) {
    return scratch((a) => {
      const h = made(a, M._el_landscape_crossings, this.pointer, point(a, from), point(a, to));
      try {
        const count = a(4);
        const p = M._el_crossings_data(h, count);
        return Array.from({length: dv().getUint32(count, true)}, (_, i) => readCrossing(p + 168 * i));
      } finally {
        M._el_crossings_destroy(h);
      }
    });
  }
  // The first entry into a solid material other than the one at `from`, or null.
  raycast(from, to) {
    return scratch((a) => {
      const hit = a(4), c = a(168);
      call(a, M._el_landscape_raycast, this.pointer, point(a, from), point(a, to), hit, c);
      return dv().getInt32(hit, true) ? readCrossing(c) : null;
    });
  }
  // The solid materials whose interiors meet the region's: a box [[x0, y0], [x1, y1]], a Shape
  // or polygons. Ascending.
  overlaps(region) {
    return scratch((a) => {
      const materials = a(256), count = a(4);
      if (region instanceof Shape || typeof region[0][0] !== 'number') {
        const s = asShape(region);
        try {
          call(a, M._el_landscape_overlaps_shape, this.pointer, s.shape.pointer, materials, count);
        } finally {
          if (s.own) s.shape.dispose();
        }
      } else {
        call(a, M._el_landscape_overlaps_box, this.pointer, box(a, region), materials, count);
      }
      return [...view(Uint8Array, materials, dv().getUint32(count, true))];
    });
  }
  // The polygons whose bounding box meets the box (default: the world), as flat arrays.
  polygonsIn(region = this.world) {
    return scratch((a) => {
      const h = made(a, M._el_landscape_polygons_in, this.pointer, box(a, region));
      try {
        return readPolygons(a, h);
      } finally {
        M._el_polygons_destroy(h);
      }
    });
  }
  // The boxes of the cells (the tree's leaves, empty ones too) that meet the box (default: the
  // world), x0, y0, x1, y1 each, as a change set's cells.
  cellsIn(region = this.world) {
    const cap = this.stats.cells;  // every cell of the world: enough for any box
    return scratch((a) => {
      const cells = a(32 * cap), needed = a(4);
      call(a, M._el_landscape_cells_in, this.pointer, box(a, region), cells, cap, needed);
      return int32s(view(BigInt64Array, cells, 4 * dv().getUint32(needed, true)));
    });
  }
  // Twice the area of a material, exact (a BigInt).
  twiceArea(material) {
    return scratch((a) => {
      const v = a(24);
      call(a, M._el_landscape_twice_area, this.pointer, material, v);
      return readInt128(v);
    });
  }
  get world() {
    return scratch((a) => {
      const b = a(32);
      call(a, M._el_landscape_world, this.pointer, b);
      const d = dv();
      const at = (k) => Number(d.getBigInt64(b + 8 * k, true));
      return [[at(0), at(1)], [at(2), at(3)]];
    });
  }
  get stats() {
    return scratch((a) => {
      const s = a(48);
      M._el_stats_init(s);
      call(a, M._el_landscape_stats, this.pointer, s);
      const d = dv();
      const at = (k) => Number(d.getBigUint64(s + 8 + 8 * k, true));
      return {polygons: at(0), vertices: at(1), cells: at(2), depth: at(3), bytes: at(4)};
    });
  }
  // The 64-bit state hash (a BigInt): equal states, equal hashes, on every platform.
  get stateHash() {
    return scratch((a) => {
      const h = a(8);
      call(a, M._el_landscape_state_hash, this.pointer, h);
      return dv().getBigUint64(h, true);
    });
  }
  // Every invariant over the whole world: the problems found (none: valid).
  check() {
    return scratch((a) => {
      const text = new TextDecoder().decode(readBytes(a, made(a, M._el_landscape_check, this.pointer)));
      return text === '' ? [] : text.trimEnd().split('\n');
    });
  }
  set checked(on) {
    scratch((a) => call(a, M._el_landscape_set_checked, this.pointer, on ? 1 : 0));
  }
  startLog() { scratch((a) => call(a, M._el_landscape_start_log, this.pointer)); }
  stopLog() { scratch((a) => call(a, M._el_landscape_stop_log, this.pointer)); }
  // The edit log (README.md, "Landscape edit logs").
  get log() {
    return scratch((a) => new TextDecoder().decode(readBytes(a, made(a, M._el_landscape_log, this.pointer))));
  }
}

// --- edit logs --------------------------------------------------------------------------------
// Replays a landscape edit log (Landscape.log's text) as `edgeland replay` does (el_replay_log):
// the edits in order up to the first bad line or refused edit, those before it kept. Returns
// {landscape (recording its own log; null when the log has no good world line: dispose() it
// otherwise), edits (applied), stopped (null, or the LoadError / InternalError that stopped it,
// `index` its line), report (the JSON text `edgeland replay` prints)}.
export function replayLog(text) {
  const bytes = new TextEncoder().encode(text);
  return scratch((a) => {
    const data = a(bytes.length);
    view(Uint8Array, data, bytes.length).set(bytes);
    const h = made(a, M._el_replay_log, data, bytes.length);
    try {
      const stopped = failure(a, M._el_replay_stopped, h);
      const report = new TextDecoder().decode(readBytes(a, made(a, M._el_replay_report, h)));
      const out = a(4);
      const noWorld = failure(a, M._el_replay_landscape, h, out);
      if (noWorld && !(noWorld instanceof LoadError)) throw noWorld;
      const landscape = noWorld ? null : new Landscape(null, 0, {}, dv().getUint32(out, true));
      return {landscape, edits: M._el_replay_edits(h) >>> 0, stopped, report};
    } finally {
      M._el_replay_destroy(h);
    }
  });
}

// The C library's version as [major, minor, patch].
export function version() {
  const v = M._el_version();
  return [v >> 16, (v >> 8) & 0xff, v & 0xff];
}

// --- the game layer (game/README.md) ----------------------------------------------------------
// Surface chains and debris islands kept in step from change sets, detach, meshes, convex pieces.
// Pass every edit's change set to every tracker, in order (detach's too); resync after a
// restored snapshot or a load.

// el_physics_materials: options {solid: [materials that collide] (default: all but 0),
// anchored: [materials that never fall], borderWall: the world border as a wall}.
function physicsMaterials(allocate, {solid = null, anchored = [], borderWall = false} = {}) {
  const m = allocate(520);
  M._el_physics_materials_init(m);
  const bytes = view(Uint8Array, m + 8, 512);
  if (solid !== null) {
    bytes.fill(0, 0, 256);
    for (const material of solid) bytes[material] = 1;
  }
  for (const material of anchored) bytes[256 + material] = 1;
  dv().setUint32(m + 4, borderWall ? 1 : 0, true);
  return m;
}

// Chains as flat arrays: chain i is info (id, closed, cell, ghosts) and the points
// xy[2 offsets[i] .. 2 offsets[i + 1]); materials[k]: the material left of the segment after
// point k (0 after an open chain's last point and along a border wall).
function readChains(allocate, h) {
  const count = allocate(4);
  const p = M._el_chains_info(h, count);
  const n = dv().getUint32(count, true);
  const d = dv();
  const at = (q) => Number(d.getBigInt64(q, true));
  const chains = Array.from({length: n}, (_, i) => {
    const q = p + 80 * i;
    return {
      id: d.getBigUint64(q + 64, true), closed: d.getUint32(q + 72, true) !== 0,
      cell: [[at(q), at(q + 8)], [at(q + 16), at(q + 24)]],
      ghostPrev: [at(q + 32), at(q + 40)], ghostNext: [at(q + 48), at(q + 56)],
    };
  });
  return {
    removed: array(allocate, M._el_chains_removed, h, BigUint64Array),
    chains,
    offsets: array(allocate, M._el_chains_offsets, h, Uint32Array),
    xy: int32s(array(allocate, M._el_chains_points, h, BigInt64Array, 2)),
    materials: array(allocate, M._el_chains_materials, h, Uint8Array),
  };
}

function chainsFrom(fn, ...args) {
  return scratch((a) => {
    const h = made(a, fn, ...args);
    try {
      return readChains(a, h);
    } finally {
      M._el_chains_destroy(h);
    }
  });
}

// The collision surface as per-cell chains with ghost vertices (C++ SurfaceTracker).
export class SurfaceTracker extends Handle {
  constructor(world, materials = {}) {
    super(scratch((a) => made(a, M._el_surface_tracker_create, world.pointer,
      physicsMaterials(a, materials))), M._el_surface_tracker_destroy);
  }
  // {removed, chains, offsets, xy, materials}: the chains the edit removed and added.
  update(world, changes) {
    return chainsFrom(M._el_surface_tracker_update, this.pointer, world.pointer, changes.pointer);
  }
  resync(world) {
    return chainsFrom(M._el_surface_tracker_resync, this.pointer, world.pointer);
  }
  // Every chain the tracker holds, by ascending id (removed is empty).
  get chains() {
    return chainsFrom(M._el_surface_tracker_chains, this.pointer);
  }
}

// Islands found by a tracker: islands[i] = {bounds, twiceArea, pieces: [polygon records]};
// detach(world, islands, i) takes one. dispose() frees them.
export class Islands extends Handle {
  constructor(pointer) {
    super(pointer, M._el_islands_destroy);
    scratch((a) => {
      const count = a(4);
      const p = M._el_islands_info(pointer, count);
      const pieces = [...readPolygons(a, M._el_islands_pieces(pointer))];
      const d = dv();
      const at = (q) => Number(d.getBigInt64(q, true));
      this.islands = Array.from({length: dv().getUint32(count, true)}, (_, i) => {
        const q = p + 64 * i;
        const first = d.getUint32(q + 56, true), n = d.getUint32(q + 60, true);
        return {bounds: [[at(q), at(q + 8)], [at(q + 16), at(q + 24)]],
          twiceArea: readInt128(q + 32), pieces: pieces.slice(first, first + n)};
      });
    });
  }
  get length() { return this.islands.length; }
}

// Debris islands found incrementally (C++ IslandTracker).
export class IslandTracker extends Handle {
  constructor(world, materials = {}) {
    super(scratch((a) => made(a, M._el_island_tracker_create, world.pointer,
      physicsMaterials(a, materials))), M._el_island_tracker_destroy);
  }
  // The islands that exist now and did not before.
  update(world, changes) {
    return scratch((a) => new Islands(made(a, M._el_island_tracker_update, this.pointer,
      world.pointer, changes.pointer)));
  }
  resync(world) {
    return scratch((a) => new Islands(made(a, M._el_island_tracker_resync, this.pointer,
      world.pointer)));
  }
  islands(world) {
    return scratch((a) => new Islands(made(a, M._el_island_tracker_islands, this.pointer,
      world.pointer)));
  }
}

// Removes islands.islands[index] from the world as one edit (StaleIsland when the world
// changed under it): {changes, regions (Polygons, ids 0), twiceArea, centroid: {x, y, den}}.
// dispose() frees it (and its change set).
export function detach(world, islands, index) {
  return scratch((a) => {
    const h = made(a, M._el_detach, world.pointer, islands.pointer, index);
    const info = a(96);
    call(a, M._el_detached_summary, h, info);
    const owner = new Handle(h, M._el_detached_destroy);
    return {
      changes: new ChangeSet(M._el_detached_changes(h), () => {}, owner),
      regions: readPolygons(a, M._el_detached_regions(h)),
      twiceArea: readInt128(info),
      centroid: {x: readInt128(info + 24), y: readInt128(info + 48), den: readInt128(info + 72)},
      dispose: () => owner.dispose(),
    };
  });
}

// Meshes: {dropped, meshes: [{id, material, vertices: Int32Array xy, triangles: Uint32Array}]}.
function readMeshes(allocate, h) {
  const polygons = readPolygons(allocate, M._el_meshes_polygons(h));
  const offsets = array(allocate, M._el_meshes_triangle_offsets, h, Uint32Array);
  const triangles = array(allocate, M._el_meshes_triangles, h, Uint32Array);
  const meshes = Array.from({length: polygons.count}, (_, i) => ({
    id: polygons.ids[i], material: polygons.materials[i],
    vertices: polygons.xy.slice(2 * polygons.offsets[i], 2 * polygons.offsets[i + 1]),
    triangles: triangles.slice(3 * offsets[i], 3 * offsets[i + 1]),
  }));
  return {dropped: array(allocate, M._el_meshes_dropped, h, BigUint64Array), meshes};
}

function meshesFrom(fn, ...args) {
  return scratch((a) => {
    const h = made(a, fn, ...args);
    try {
      return readMeshes(a, h);
    } finally {
      M._el_meshes_destroy(h);
    }
  });
}

// The meshes an edit drops and builds, from its change set alone.
export function meshUpdate(changes) { return meshesFrom(M._el_mesh_update, changes.pointer); }
export function allMeshes(world) { return meshesFrom(M._el_all_meshes, world.pointer).meshes; }

// A valid polygon ([[x, y], ...]) as strictly convex pieces of at most maxVertices vertices.
export function convexPieces(polygon, maxVertices = 8) {
  return scratch((a) => {
    const points = a(16 * polygon.length);
    polygon.forEach((p, i) => writePoint(points + 16 * i, p));
    const h = made(a, M._el_convex_pieces, points, polygon.length, maxVertices);
    try {
      return [...readPolygons(a, h)].map((p) => p.points);
    } finally {
      M._el_polygons_destroy(h);
    }
  });
}

// --- the game driver (game/README.md, "The game driver") -------------------------------------
// What a game uses: one driver owns a snapshot of a landscape and everything derived from it.
// Each frame's edits go in as one batch (apply([Edit.carve(shape), ...])) and an update comes out:
// the change set, the chains to remove and add (with ghost vertices), the meshes to drop and
// build, and the islands that broke off as debris bodies.

// One edit of a frame: Edit.carve(shape), fill(shape, m), fillEmpty(shape, m), replace(shape,
// from, to), relabel(shape, [[from, to], ...] or a Map). The shape is a Shape or polygons.
export const Edit = {
  carve: (shape) => ({kind: 'carve', shape, materials: []}),
  fill: (shape, material) => ({kind: 'fill', shape, materials: [material]}),
  fillEmpty: (shape, material) => ({kind: 'fill_empty', shape, materials: [material]}),
  replace: (shape, from, to) => ({kind: 'replace', shape, materials: [from, to]}),
  relabel: (shape, pairs) => ({kind: 'relabel', shape,
    materials: [...(pairs instanceof Map ? pairs.entries() : pairs)].flat()}),
};

const EDIT_FUNCTIONS = {carve: '_el_edits_carve', fill: '_el_edits_fill',
  fill_empty: '_el_edits_fill_empty', replace: '_el_edits_replace'};

// An el_edits batch of `edits`, made in scratch memory's lifetime by the caller (destroyed by it).
function editsBatch(allocate, edits) {
  const batch = made(allocate, M._el_edits_create);
  try {
    for (const e of edits) {
      const s = asShape(e.shape);
      try {
        if (e.kind === 'relabel') {
          const fromTo = allocate(4 * Math.max(1, e.materials.length));
          e.materials.forEach((m, i) => dv().setInt32(fromTo + 4 * i, m, true));
          call(allocate, M._el_edits_relabel, batch, s.shape.pointer, fromTo, e.materials.length / 2);
        } else if (EDIT_FUNCTIONS[e.kind]) {
          call(allocate, M[EDIT_FUNCTIONS[e.kind]], batch, s.shape.pointer, ...e.materials);
        } else {
          throw new TypeError(`unknown edit kind ${e.kind}`);
        }
      } finally {
        if (s.own) s.shape.dispose();
      }
    }
    return batch;
  } catch (error) {
    M._el_edits_destroy(batch);
    throw error;
  }
}

// el_game_options: {solid, anchored, borderWall, meshes = true, debris = true,
// maxPieceVertices = 8, debrisBudget = 8192, maxDebrisWait = 3}.
function gameOptions(allocate, options = {}) {
  const known = ['solid', 'anchored', 'borderWall', 'meshes', 'debris', 'maxPieceVertices',
    'debrisBudget', 'maxDebrisWait'];
  for (const name of Object.keys(options)) {
    if (!known.includes(name)) throw new TypeError(`unknown game option ${name}`);
  }
  const {solid = null, anchored = [], borderWall = false, meshes = true, debris = true} = options;
  const o = allocate(536);
  M._el_game_options_init(o);
  const d = dv();
  d.setUint32(o + 4, (meshes ? 1 : 0) | (debris ? 2 : 0) | (borderWall ? 4 : 0), true);
  if (options.debrisBudget !== undefined) d.setBigUint64(o + 8, BigInt(options.debrisBudget), true);
  if (options.maxPieceVertices !== undefined) d.setUint32(o + 16, options.maxPieceVertices, true);
  if (options.maxDebrisWait !== undefined) d.setUint32(o + 20, options.maxDebrisWait, true);
  const bytes = view(Uint8Array, o + 24, 512);
  if (solid !== null) {
    bytes.fill(0, 0, 256);
    for (const material of solid) bytes[material] = 1;
  }
  for (const material of anchored) bytes[256 + material] = 1;
  return o;
}

// The debris bodies of an update: [{bounds, twiceArea, centroid: {x, y, den}, regions, pieces
// (Polygons: material per polygon, ids 0), meshes}].
function readDebris(allocate, h) {
  const regions = readPolygons(allocate, M._el_game_update_debris_regions(h));
  const pieces = readPolygons(allocate, M._el_game_update_debris_pieces(h));
  const meshes = readMeshes(allocate, M._el_game_update_debris_meshes(h)).meshes;
  const count = allocate(4);
  const p = M._el_game_update_debris(h, count);
  const d = dv();
  const at = (q) => Number(d.getBigInt64(q, true));
  const part = (all, first, n) => [...all].slice(first, first + n);
  return Array.from({length: d.getUint32(count, true)}, (_, i) => {
    const q = p + 144 * i;
    const firstRegion = d.getUint32(q + 128, true), regionCount = d.getUint32(q + 132, true);
    const firstPiece = d.getUint32(q + 136, true), pieceCount = d.getUint32(q + 140, true);
    return {
      bounds: [[at(q), at(q + 8)], [at(q + 16), at(q + 24)]],
      twiceArea: readInt128(q + 32),
      centroid: {x: readInt128(q + 56), y: readInt128(q + 80), den: readInt128(q + 104)},
      regions: part(regions, firstRegion, regionCount).map(({material, points}) => ({material, points})),
      pieces: part(pieces, firstPiece, pieceCount).map(({material, points}) => ({material, points})),
      meshes: meshes.slice(firstRegion, firstRegion + (meshes.length ? regionCount : 0)),
    };
  });
}

// What one driver call changed: {changes (a ChangeSet, borrowed: dispose() frees the update), chains
// ({removed, chains, offsets, xy, materials}), meshes ({dropped, meshes}), debris, work}.
function readUpdate(h) {
  const owner = new Handle(h, M._el_game_update_destroy);
  return scratch((a) => {
    const w = a(56);
    M._el_game_work_init(w);
    call(a, M._el_game_update_work, h, w);
    const d = dv();
    const at = (k) => Number(d.getBigUint64(w + 8 + 8 * k, true));
    return {
      changes: new ChangeSet(M._el_game_update_changes(h), () => {}, owner),
      chains: readChains(a, M._el_game_update_chains(h)),
      meshes: readMeshes(a, M._el_game_update_meshes(h)),
      debris: readDebris(a, h),
      work: {cellsScanned: at(0), boundaryPasses: at(1), cellsTraced: at(2), islandsFound: at(3),
        islandsDetached: at(4), debrisWaiting: at(5)},
      dispose: () => owner.dispose(),
    };
  });
}

// The game driver (C++ GameDriver) over a snapshot of `world` (the Landscape stays the caller's).
export class GameDriver extends Handle {
  constructor(world, options = {}) {
    super(scratch((a) => made(a, M._el_game_driver_create, world.pointer, gameOptions(a, options))),
      M._el_game_driver_destroy);
  }
  // The frame's edits, in order, as one batch. A typed error (InvalidMaterial, LimitExceeded,
  // ...) leaves the driver and its world as they were. No edits: only the debris queue moves.
  apply(edits = []) {
    return readUpdate(scratch((a) => {
      const batch = editsBatch(a, edits);
      try {
        return made(a, M._el_game_driver_apply, this.pointer, batch);
      } finally {
        M._el_edits_destroy(batch);
      }
    }));
  }
  // The world replaced by a snapshot of `world` (an undo, a load): the update names exactly
  // what changed.
  reset(world) {
    return readUpdate(scratch((a) => made(a, M._el_game_driver_reset, this.pointer, world.pointer)));
  }
  // Whether the last update's fills buried a body whose bounding box is [[x0, y0], [x1, y1]].
  buried(region) {
    return scratch((a) => {
      const out = a(4);
      call(a, M._el_game_driver_buried, this.pointer, box(a, region), out);
      return dv().getInt32(out, true) !== 0;
    });
  }
  // A snapshot of the driver's world (O(1)): queries, saves, the state hash. Dispose it.
  get landscape() {
    return scratch((a) => new Landscape(null, 0, {}, made(a, M._el_game_driver_landscape, this.pointer)));
  }
  // Every chain now, by ascending id ({chains, offsets, xy, materials}; removed is empty).
  get chains() { return chainsFrom(M._el_game_driver_chains, this.pointer); }
  get debrisWaiting() { return M._el_game_driver_debris_waiting(this.pointer); }
}
