// TypeScript declarations of the edgeland package (index.js): the C API's surface with
// JavaScript names. Coordinates are numbers (exact: every coordinate lies within 2^31 - 1);
// ids, hashes and exact 128-bit values are BigInts.

export type XY = [number, number];
/** A closed axis-aligned box: [[x0, y0], [x1, y1]]. */
export type BoxXY = [XY, XY];
/** Polygons, each an array of points, counter-clockwise. */
export type PolygonList = XY[][];

/** The C library's version: [major, minor, patch]. */
export function version(): [number, number, number];

export const RULES: readonly string[];

/** Every edgeland error: the el_status and the el_error fields. */
export class EdgelandError extends Error {
  readonly status: number;
  /** The rule broken, the configuration setting or the limit (edgeland.h's EL_RULE_* ...). */
  readonly kind: number;
  readonly operand: number;
  /** The polygon (input errors), the byte offset (LoadError of a save; a replay's: the line),
   * ...; null when none. */
  readonly index: number | null;
  /** The vertex or edge of an input error; null when none. */
  readonly vertex: number | null;
  /** The value given: a material number, a count requested, an argument. */
  readonly value: number;
  /** The largest value accepted. */
  readonly limit: number;
  /** The least value accepted. */
  readonly minimum: number;
  /** The offending point of an input error. */
  readonly where: XY;
}
/** A shape breaks a rule of validate(). */
export class InvalidInput extends EdgelandError {
  /** The rule's name, e.g. "self-intersection". */
  readonly rule: string;
}
/** A coordinate beyond 2^31 - 1. */
export class CoordinateOutOfRange extends InvalidInput {}
export class InvalidBox extends InvalidInput {}
/** A material number outside 0..255 (`value`). */
export class InvalidMaterial extends EdgelandError {}
/** The world box or the configuration (`kind`: the setting). */
export class InvalidConfig extends EdgelandError {}
/** A landscape limit (`kind`: which, `value` requested, `limit` the maximum). */
export class LimitExceeded extends EdgelandError {}
/** A save that cannot be read (`index`: the byte offset), or the line a replay stopped at. */
export class LoadError extends EdgelandError {}
/** A delta that cannot be read or applied (`index`: the byte offset). */
export class DeltaError extends EdgelandError {}
/** A delta of another world, version, base or result (`kind`: the field). */
export class DeltaMismatch extends EdgelandError {}
/** A tree path that names no node (`index`: the path's length). */
export class InvalidPath extends EdgelandError {}
/** An edit or query reached an unloaded region (`index`: its path's length). */
export class RegionNotLoaded extends EdgelandError {}
/** A polygon id the landscape no longer holds (`index`: the id). */
export class UnknownPolygon extends EdgelandError {}
/** The island changed since it was found (`index`: the first polygon id missing). */
export class StaleIsland extends EdgelandError {}
export class IndexOutOfRange extends EdgelandError {}
/** A number below its minimum (`minimum`). */
export class InvalidArgument extends EdgelandError {}
/** A shape builder's number outside its range. */
export class ArgumentOutOfRange extends EdgelandError {}

/** One polygon of a Polygons list. */
export interface PolygonRecord {
  id: bigint;
  material: number;
  cell: BoxXY;
  points: XY[];
}

/** Polygons as flat arrays: polygon i has ids[i], materials[i], its cell's box
 * cells[4i .. 4i + 3] (x0, y0, x1, y1) and the points xy[2 offsets[i] .. 2 offsets[i + 1]). */
export class Polygons implements Iterable<PolygonRecord> {
  readonly ids: BigUint64Array;
  readonly materials: Uint8Array;
  readonly cells: Int32Array;
  readonly offsets: Uint32Array;
  readonly xy: Int32Array;
  readonly count: number;
  polygon(i: number): PolygonRecord;
  [Symbol.iterator](): Iterator<PolygonRecord>;
}

/** What an edit changed. It keeps the C change set for the game layer: dispose() frees it. */
export class ChangeSet implements Disposable {
  /** Ids that no longer exist, ascending. */
  readonly removed: BigUint64Array;
  /** The polygons added, ascending id. */
  readonly added: Polygons;
  /** The cells rebuilt, 4 numbers each (x0, y0, x1, y1). */
  readonly cells: Int32Array;
  /** Twice the change of area per material, exact; the values sum to 0. */
  readonly areaDelta: Map<number, bigint>;
  dispose(): void;
}

/** An exact fraction. */
export interface Fraction {
  num: bigint;
  den: bigint;
}

/** A material change along a segment (C++ MaterialCrossing). */
export interface Crossing {
  /** The parameter along the segment, exact. */
  t: Fraction;
  /** The point (x / den, y / den), exact. */
  point: {x: bigint; y: bigint; den: bigint};
  rounded: XY;
  /** The edge's outward normal (dy, -dx), not normalised. */
  normal: XY;
  /** The polygon entered (after != 0), else the one left. */
  polygon: bigint;
  edge: number;
  before: number;
  after: number;
}

export interface LandscapeOptions {
  tree?: 'quadtree' | 'kd';
  edgeCap?: number;
  mergeBelow?: number;
  minCellSize?: number;
  /** -1: adaptive. */
  gridDepth?: number;
  /** Every edit re-verifies every invariant (tests, tools). */
  checked?: boolean;
  maxVertices?: number;
  maxShapeVertices?: number;
  maxCells?: number;
}

export interface LandscapeStats {
  polygons: number;
  vertices: number;
  cells: number;
  depth: number;
  bytes: number;
}

/** Objects holding WebAssembly memory: dispose() frees it at once. */
interface Disposable {
  dispose(): void;
}

/** A polygon set validated once: strictly simple, counter-clockwise, hole-free polygons with
 * disjoint interiors. */
export class Shape implements Disposable {
  constructor(polygons: PolygonList);
  static circle(center: XY, radius: number): Shape;
  static regularPolygon(center: XY, radius: number, sides: number, phase?: [number, number]): Shape;
  static capsule(from: XY, to: XY, radius: number): Shape;
  static box(lo: XY, hi: XY): Shape;
  static rotatedBox(center: XY, halfWidth: number, halfHeight: number,
                    angle?: [number, number]): Shape;
  /** Any polygons read with OGC semantics (el_shape_import): each polygon its exterior ring,
   * then its holes, clockwise or self-intersecting as drawn; the shape is the valid hole-free
   * pieces of the region they enclose (none for rings of no area). */
  static import(polygons: XY[][][]): Shape;
  readonly polygons: PolygonList;
  dispose(): void;
}

/** A shape argument: a Shape, or polygons made into one for the call. */
export type ShapeLike = Shape | PolygonList;

/** A changeable world of materials 0..255. A failed edit throws and leaves it as it was. */
export class Landscape implements Disposable {
  constructor(world: BoxXY, fill?: number, options?: LandscapeOptions);
  /** A snapshot in O(1). */
  clone(): Landscape;
  save(): Uint8Array;
  static load(bytes: Uint8Array, limits?: Pick<LandscapeOptions, 'maxVertices' | 'maxShapeVertices' | 'maxCells'>): Landscape;
  carve(shape: ShapeLike): ChangeSet;
  fill(shape: ShapeLike, material: number): ChangeSet;
  fillEmpty(shape: ShapeLike, material: number): ChangeSet;
  replace(shape: ShapeLike, from: number, to: number): ChangeSet;
  relabel(shape: ShapeLike, pairs: Iterable<[number, number]> | Map<number, number>): ChangeSet;
  materialAt(p: XY): number;
  crossings(from: XY, to: XY): Crossing[];
  raycast(from: XY, to: XY): Crossing | null;
  overlaps(region: BoxXY | ShapeLike): number[];
  polygonsIn(box?: BoxXY): Polygons;
  /** The boxes of the cells (empty ones too) that meet the box (default: the world), 4 numbers
   * each (x0, y0, x1, y1). */
  cellsIn(box?: BoxXY): Int32Array;
  twiceArea(material: number): bigint;
  readonly world: BoxXY;
  readonly stats: LandscapeStats;
  readonly stateHash: bigint;
  check(): string[];
  set checked(on: boolean);
  startLog(): void;
  stopLog(): void;
  readonly log: string;
  dispose(): void;
}

/** A replayed edit log (replayLog). */
export interface Replay {
  /** The replayed world, recording its own log; null when the log has no good world line. */
  landscape: Landscape | null;
  /** The edits applied. */
  edits: number;
  /** Why the replay stopped before the log's end (`index`: the line), or null. */
  stopped: EdgelandError | null;
  /** The JSON text `edgeland replay` prints for the log. */
  report: string;
}

/** Replays a landscape edit log (Landscape.log's text) as `edgeland replay` does: the edits in
 * order up to the first bad line or refused edit, those before it kept. */
export function replayLog(text: string): Replay;

// --- the game layer ---------------------------------------------------------------------------

export interface PhysicsMaterials {
  /** The materials that collide (default: every one but 0). */
  solid?: Iterable<number>;
  /** The materials that never fall. */
  anchored?: Iterable<number>;
  /** The world border as a wall around the non-solid parts. */
  borderWall?: boolean;
}

export interface ChainRecord {
  id: bigint;
  closed: boolean;
  cell: BoxXY;
  ghostPrev: XY;
  ghostNext: XY;
}

/** Chains as flat arrays: chain i is chains[i] and the points xy[2 offsets[i] .. 2 offsets[i + 1]);
 * materials[k] is the material left of the segment after point k. */
export interface Chains {
  removed: BigUint64Array;
  chains: ChainRecord[];
  offsets: Uint32Array;
  xy: Int32Array;
  materials: Uint8Array;
}

export class SurfaceTracker implements Disposable {
  constructor(world: Landscape, materials?: PhysicsMaterials);
  update(world: Landscape, changes: ChangeSet): Chains;
  resync(world: Landscape): Chains;
  readonly chains: Chains;
  dispose(): void;
}

export interface IslandRecord {
  bounds: BoxXY;
  twiceArea: bigint;
  pieces: PolygonRecord[];
}

export class Islands implements Disposable {
  readonly islands: IslandRecord[];
  readonly length: number;
  dispose(): void;
}

export class IslandTracker implements Disposable {
  constructor(world: Landscape, materials?: PhysicsMaterials);
  update(world: Landscape, changes: ChangeSet): Islands;
  resync(world: Landscape): Islands;
  islands(world: Landscape): Islands;
  dispose(): void;
}

export interface Detached extends Disposable {
  changes: ChangeSet;
  regions: Polygons;
  twiceArea: bigint;
  centroid: {x: bigint; y: bigint; den: bigint};
}
export function detach(world: Landscape, islands: Islands, index: number): Detached;

export interface Mesh {
  id: bigint;
  material: number;
  /** The polygon's own vertices, 2 numbers each. */
  vertices: Int32Array;
  /** Counter-clockwise index triples into the vertices. */
  triangles: Uint32Array;
}
export function meshUpdate(changes: ChangeSet): {dropped: BigUint64Array; meshes: Mesh[]};
export function allMeshes(world: Landscape): Mesh[];
export function convexPieces(polygon: XY[], maxVertices?: number): XY[][];


// --- the game driver: what a game uses ----------------------------------------------------------

export interface EditRecord {
  kind: 'carve' | 'fill' | 'fill_empty' | 'replace' | 'relabel';
  shape: ShapeLike;
  materials: number[];
}
/** One edit of a frame's batch (C++ Edit). */
export const Edit: {
  carve(shape: ShapeLike): EditRecord;
  fill(shape: ShapeLike, material: number): EditRecord;
  fillEmpty(shape: ShapeLike, material: number): EditRecord;
  replace(shape: ShapeLike, from: number, to: number): EditRecord;
  relabel(shape: ShapeLike, pairs: Iterable<[number, number]> | Map<number, number>): EditRecord;
};

export interface GameOptions extends PhysicsMaterials {
  /** Render meshes in each update (default true). */
  meshes?: boolean;
  /** Islands found and detached as debris (default true). */
  debris?: boolean;
  /** Debris bodies' convex pieces have at most this many vertices (3 or more; default 8). */
  maxPieceVertices?: number;
  /** Island vertices one update may detach (default 4096). */
  debrisBudget?: number | bigint;
  /** Updates an island may wait (default 3). */
  maxDebrisWait?: number;
}

export interface DebrisPart {
  material: number;
  points: XY[];
}
/** An island taken out of the landscape, ready to become a dynamic body. */
export interface Debris {
  bounds: BoxXY;
  twiceArea: bigint;
  centroid: {x: bigint; y: bigint; den: bigint};
  /** The island's region as maximal polygons per material. */
  regions: DebrisPart[];
  /** Their convex pieces: one fixture each. */
  pieces: DebrisPart[];
  /** The regions' meshes (with `meshes`), ids 0. */
  meshes: Mesh[];
}

export interface GameWork {
  cellsScanned: number;
  boundaryPasses: number;
  cellsTraced: number;
  islandsFound: number;
  islandsDetached: number;
  debrisWaiting: number;
}

/** What one driver call changed; dispose() frees it (its change set with it). */
export interface GameUpdate extends Disposable {
  changes: ChangeSet;
  chains: Chains;
  meshes: {dropped: BigUint64Array; meshes: Mesh[]};
  debris: Debris[];
  work: GameWork;
}

export class GameDriver implements Disposable {
  constructor(world: Landscape, options?: GameOptions);
  apply(edits?: EditRecord[]): GameUpdate;
  reset(world: Landscape): GameUpdate;
  buried(box: BoxXY): boolean;
  readonly landscape: Landscape;
  readonly chains: Chains;
  readonly debrisWaiting: number;
  dispose(): void;
}
