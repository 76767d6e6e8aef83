/* edgeland.h: the C API of edgeland (capi/README.md).
 *
 * C99 with <stdint.h> and <stddef.h> only; every function is `el_*`, every type `el_*`.
 * A thin translation of the C++ library: each call does what the C++ call of the same name
 * does, with the same guarantees (an edit that fails leaves the landscape bit for bit as it
 * was; results are exact and the same on every platform) and the same errors, as codes.
 *
 * CONVENTIONS
 *   * Handles are opaque pointers (el_landscape, el_shape, el_changes, ...), made by one
 *     function and freed by its el_*_destroy, which takes NULL as a no-op. Nothing is global:
 *     distinct handles may be used from distinct threads; one handle must not be changed
 *     while used elsewhere (as a C++ Landscape).
 *   * Fallible functions return an el_status (EL_OK = 0) and take an optional `el_error*` last
 *     (NULL: no details). No function throws, aborts or longjmps across this border; out of
 *     memory is EL_OUT_OF_MEMORY. On failure, out-parameters are left as they were.
 *   * Arrays in are copied: polygon sets as CSR, `xy` holding x0, y0, x1, y1, ... and
 *     `offsets[0..n]` (polygon i is points offsets[i] .. offsets[i + 1] - 1; offsets[0] = 0).
 *   * Arrays out live in a result handle: `el_X_field(h, &count)` returns a pointer valid until
 *     h is destroyed (NULL with count 0 when empty), `el_X_copy_field(h, buf, cap, &needed)`
 *     copies into the caller's buffer (EL_BUFFER_TOO_SMALL with `needed` set when cap is less;
 *     buf may then be NULL).
 *   * Exact 128-bit values (twice areas, the parts of exact points) are el_int128: the two's
 *     complement words {lo, hi} and `approx`, the nearest double.
 *   * Materials go in as int32_t and are checked (0..255, else EL_INVALID_MATERIAL), so no
 *     number wraps into another material; they come out as uint8_t.
 *   * Configuration structs begin with `struct_size` (set it with the matching el_*_init):
 *     fields are only ever added at the end. Flags are fixed-width integers.
 *   * The ABI only grows: functions and fields are added, never changed or removed (ctest
 *     capi.abi compares the library with capi/abi/edgeland_c.abi).
 */
#ifndef EDGELAND_EDGELAND_H
#define EDGELAND_EDGELAND_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#if defined(EL_BUILDING_DLL)
#define EL_API __declspec(dllexport)
#elif defined(EL_STATIC)
#define EL_API
#else
#define EL_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define EL_API __attribute__((visibility("default")))
#else
#define EL_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- version ------------------------------------------------------------------------------ */

/* 0x00MMmmpp: major, minor, patch. A library with the header's major and at least its minor
 * has every function the header declares. */
#define EL_VERSION_MAJOR 1
#define EL_VERSION_MINOR 0
#define EL_VERSION_PATCH 0
#define EL_VERSION ((EL_VERSION_MAJOR << 16) | (EL_VERSION_MINOR << 8) | EL_VERSION_PATCH)

/* The library's EL_VERSION. */
EL_API uint32_t el_version(void);
/* EL_OK when the library serves a program built with this header (pass EL_VERSION), else
 * EL_VERSION_MISMATCH: another major, or an older minor. */
EL_API int32_t el_check_version(uint32_t header_version);

/* ---- statuses and errors ------------------------------------------------------------------- */

typedef int32_t el_status;
/* One code per edgeland error class (the C++ name in brackets), plus the border's own. */
enum {
  EL_OK = 0,
  EL_NULL_ARGUMENT = 1,    /* a required pointer argument was NULL */
  EL_OUT_OF_MEMORY = 2,    /* std::bad_alloc */
  EL_VERSION_MISMATCH = 3, /* a struct_size this library does not know, el_check_version */
  EL_INTERNAL = 4,         /* a bug in edgeland [LandscapeInternalError, InternalError, other] */
  EL_INVALID_INPUT = 10,   /* a shape breaks a rule of validate() [InvalidInput] */
  EL_COORDINATE_OUT_OF_RANGE = 11, /* beyond |c| <= 2^31 - 1 [CoordinateOutOfRange] */
  EL_INVALID_BOX = 12,             /* [InvalidBox] */
  EL_TOO_MANY_VERTICES = 13,       /* [TooManyVertices] */
  EL_INVALID_ARGUMENT = 14,        /* a number below its minimum [InvalidArgument] */
  EL_ARGUMENT_OUT_OF_RANGE = 15,   /* a number outside its range [ArgumentOutOfRange] */
  EL_NON_POSITIVE_AREA = 16,       /* [NonPositiveArea] */
  EL_INVALID_OVERLAY = 17,         /* [InvalidOverlay] */
  EL_INVALID_CONFIG = 20,          /* world box or configuration [InvalidConfig] */
  EL_INVALID_MATERIAL = 21,        /* a material number outside 0..255 [InvalidMaterial] */
  EL_LIMIT_EXCEEDED = 22,          /* [LimitExceeded] */
  EL_LOAD_ERROR = 23,              /* a save that cannot be read [LoadError] */
  EL_DELTA_ERROR = 24,             /* a delta that cannot be read or applied [DeltaError] */
  EL_DELTA_MISMATCH = 25,          /* a delta of another world, version, base or result
                                      [DeltaMismatch] */
  EL_INVALID_PATH = 26,            /* a tree path that names no node [InvalidPath] */
  EL_REGION_NOT_LOADED = 27,       /* an edit or query reached an unloaded region
                                      [RegionNotLoaded] */
  EL_UNKNOWN_POLYGON = 28,         /* a polygon id the landscape no longer holds
                                      [UnknownPolygon] */
  EL_STALE_ISLAND = 30,            /* the island changed since it was found [StaleIsland] */
  EL_INDEX_OUT_OF_RANGE = 40,      /* an index past a result's count */
  EL_BUFFER_TOO_SMALL = 41         /* copy_to: `cap` below `needed` */
};

/* EL_ERROR_KIND_* values of el_error.kind, by status:
 *   input errors (10..12): the rule broken, as validate() names it (EL_RULE_*);
 *   EL_INVALID_CONFIG: the setting (EL_SETTING_*); EL_LIMIT_EXCEEDED: the limit (EL_LIMIT_*);
 *   EL_INVALID_OVERLAY: the reason (0 label count, 1 zero label, 2 outside window, 3 bad
 *   window, 4 windows overlap). */
enum {
  EL_RULE_TOO_FEW_VERTICES = 0,
  EL_RULE_COORDINATE_OUT_OF_RANGE = 1,
  EL_RULE_REPEATED_VERTEX = 2,
  EL_RULE_SELF_INTERSECTION = 3,
  EL_RULE_SPIKE = 4,
  EL_RULE_NOT_COUNTER_CLOCKWISE = 5,
  EL_RULE_OVERLAPPING_INTERIORS = 6,
  EL_RULE_INVERTED_BOX = 7
};
enum {
  EL_SETTING_WORLD_OUT_OF_RANGE = 0,
  EL_SETTING_WORLD_EMPTY = 1,
  EL_SETTING_EDGE_CAP = 2,
  EL_SETTING_MERGE_BELOW = 3,
  EL_SETTING_MIN_CELL_SIZE = 4,
  EL_SETTING_GRID_DEPTH = 5,
  EL_SETTING_TREE = 6,
  EL_SETTING_GRID_DEPTH_BEYOND_CELLS = 7
};
enum {
  EL_LIMIT_VERTICES = 0,
  EL_LIMIT_SHAPE_VERTICES = 1,
  EL_LIMIT_CELLS = 2,
  EL_LIMIT_POLYGON_IDS = 3
};
/* el_error.operand for input errors: which argument. */
enum {
  EL_OPERAND_SUBJECT = 0,
  EL_OPERAND_CLIP = 1, /* an edit's shape */
  EL_OPERAND_RINGS = 2,
  EL_OPERAND_QUERY = 3,
  EL_OPERAND_POLYGON = 4,
  EL_OPERAND_SHAPE = 5 /* a shape builder's arguments */
};
#define EL_NONE UINT64_MAX

typedef struct el_point {
  int64_t x, y;
} el_point;

typedef struct el_box {
  el_point min, max; /* closed: min.x <= x <= max.x, min.y <= y <= max.y */
} el_box;

/* What went wrong, with its data. Set struct_size = sizeof(el_error) (el_error_init). Fields a
 * status does not use are 0, or EL_NONE for indices. */
typedef struct el_error {
  uint32_t struct_size;
  el_status status;
  uint32_t kind;     /* EL_RULE_*, EL_SETTING_*, EL_LIMIT_*, the overlay reason (above) or a
                        delta mismatch's field (0 world, 1 algorithm, 2 base, 3 result,
                        4 node hash) */
  uint32_t operand;  /* EL_OPERAND_* for input errors */
  uint64_t index;    /* input: the polygon; load, delta: the byte offset (a replay: the log's
                        line); stale island, unknown polygon: the polygon id; a tree path or
                        region: the path's length;
                        overlay: the member or window; argument errors: the argument's position */
  uint64_t vertex;   /* input: the vertex or edge (EL_NONE if none) */
  int64_t value;     /* the value given: a material number, a count requested, an argument */
  int64_t limit;     /* the largest accepted (LIMIT_EXCEEDED, TOO_MANY_VERTICES, ARGUMENT_*) */
  int64_t minimum;   /* the least accepted (INVALID_ARGUMENT, ARGUMENT_OUT_OF_RANGE) */
  el_point where;    /* input: the offending point */
  char message[256]; /* the C++ error's message, NUL-terminated, cut at 255 bytes */
} el_error;

EL_API void el_error_init(el_error* error);
/* A stable name, e.g. "EL_INVALID_INPUT"; "EL_UNKNOWN" for a code not listed above. */
EL_API const char* el_status_name(el_status status);

/* ---- exact values --------------------------------------------------------------------------- */

/* A 128-bit integer: hi * 2^64 + lo (two's complement), and the nearest double. */
typedef struct el_int128 {
  uint64_t lo;
  int64_t hi;
  double approx;
} el_int128;

/* A material change along a segment (C++ MaterialCrossing): at from + t (to - from) with
 * t = t_num / t_den, the exact point (x_num / den, y_num / den), its rounding, the polygon
 * entered (after != 0) or left and its edge, the edge's outward normal (dy, -dx). */
typedef struct el_crossing {
  el_int128 t_num, t_den;
  el_int128 x_num, y_num, den;
  el_point rounded;
  el_point normal;
  uint64_t polygon;
  uint32_t edge;
  uint8_t before, after;
  uint8_t reserved[2];
} el_crossing;

/* Twice the change of one material's area (exact). */
typedef struct el_area_delta {
  el_int128 twice_area;
  uint32_t material;
  uint32_t reserved;
} el_area_delta;

/* ---- handles ----------------------------------------------------------------------------------
 */

typedef struct el_landscape el_landscape; /* a world (C++ Landscape) */
typedef struct el_shape el_shape;         /* a validated polygon set (C++ ValidSet) */
typedef struct el_changes el_changes;     /* what an edit changed (C++ ChangeSet) */
typedef struct el_polygons el_polygons;   /* polygons with ids, materials and cells */
typedef struct el_crossings el_crossings; /* material changes along a segment */
typedef struct el_bytes el_bytes;         /* bytes: a save, a log, a report */

/* ---- shapes -----------------------------------------------------------------------------------
 */

/* A polygon set from CSR arrays, validated once (InvalidInput / CoordinateOutOfRange with the
 * polygon and vertex otherwise, operand EL_OPERAND_CLIP): strictly simple, counter-clockwise,
 * hole-free polygons with disjoint interiors. */
EL_API el_status el_shape_create(const int64_t* xy, const uint32_t* offsets, size_t polygon_count,
                                 el_shape** out, el_error* error);
/* kernel/shapes.hpp's builders, valid by construction: a circle (radius 1 .. 2^33), a regular
 * polygon (3 .. 65536 sides, the first corner at phase_num / phase_den turns), a capsule from a
 * to b, an axis-aligned box, a box of half extents turned by angle_num / angle_den turns. */
EL_API el_status el_shape_circle(const el_point* center, int64_t radius, el_shape** out,
                                 el_error* error);
EL_API el_status el_shape_regular_polygon(const el_point* center, int64_t radius, int64_t sides,
                                          int64_t phase_num, int64_t phase_den, el_shape** out,
                                          el_error* error);
EL_API el_status el_shape_capsule(const el_point* a, const el_point* b, int64_t radius,
                                  el_shape** out, el_error* error);
EL_API el_status el_shape_box(const el_box* box, el_shape** out, el_error* error);
EL_API el_status el_shape_rotated_box(const el_point* center, int64_t half_width,
                                      int64_t half_height, int64_t angle_num, int64_t angle_den,
                                      el_shape** out, el_error* error);
/* A shape from any polygons, read with OGC semantics (clip.hpp import_polygons): the region a
 * polygon of another library or of an editor encloses, with clockwise or self-intersecting
 * rings and holes, as valid hole-free polygons (none for rings of no area). Polygon i is the
 * rings polygon_rings[i] .. polygon_rings[i + 1] - 1 (its exterior, then its holes), ring r the
 * points ring_offsets[r] .. ring_offsets[r + 1] - 1 of xy (CSR twice: polygon_rings[0] = 0,
 * ring_offsets[0] = 0). A coordinate beyond the bound is EL_COORDINATE_OUT_OF_RANGE (operand
 * EL_OPERAND_RINGS, index the polygon, vertex the vertex within its ring). */
EL_API el_status el_shape_import(const int64_t* xy, const uint32_t* ring_offsets,
                                 const uint32_t* polygon_rings, size_t polygon_count,
                                 el_shape** out, el_error* error);
/* The shape's polygons (ids, materials and cells 0). */
EL_API el_status el_shape_polygons(const el_shape* shape, el_polygons** out, el_error* error);
EL_API void el_shape_destroy(el_shape* shape);

/* ---- landscapes -------------------------------------------------------------------------------
 */

enum { EL_TREE_QUADTREE = 0, EL_TREE_KD = 1 };
enum { EL_LANDSCAPE_CHECKED = 1 }; /* el_landscape_config.flags */

/* C++ LandscapeConfig and LandscapeLimits (spatial/.../types.hpp has what each means). */
typedef struct el_landscape_config {
  uint32_t struct_size;
  uint32_t tree; /* EL_TREE_* */
  uint32_t edge_cap;
  uint32_t merge_below;
  int64_t min_cell_size;
  int32_t grid_depth; /* -1: adaptive */
  uint32_t flags;     /* EL_LANDSCAPE_CHECKED: re-verify every edit (tests, tools) */
  uint64_t max_vertices;
  uint64_t max_shape_vertices;
  uint64_t max_cells;
} el_landscape_config;

/* The defaults of the C++ library, struct_size = sizeof(el_landscape_config). */
EL_API void el_landscape_config_init(el_landscape_config* config);

/* A world over the box, empty or filled with `fill`; config NULL: the defaults. */
EL_API el_status el_landscape_create(const el_box* world, int32_t fill,
                                     const el_landscape_config* config, el_landscape** out,
                                     el_error* error);
/* A snapshot: O(1), the tree is shared; edits of either never show in the other. */
EL_API el_status el_landscape_clone(const el_landscape* landscape, el_landscape** out,
                                    el_error* error);
EL_API void el_landscape_destroy(el_landscape* landscape);

/* Edits. `changes` may be NULL (not wanted); else *changes gets a new change set. */
EL_API el_status el_landscape_carve(el_landscape* landscape, const el_shape* shape,
                                    el_changes** changes, el_error* error);
EL_API el_status el_landscape_fill(el_landscape* landscape, const el_shape* shape, int32_t material,
                                   el_changes** changes, el_error* error);
EL_API el_status el_landscape_fill_empty(el_landscape* landscape, const el_shape* shape,
                                         int32_t material, el_changes** changes, el_error* error);
EL_API el_status el_landscape_replace(el_landscape* landscape, const el_shape* shape, int32_t from,
                                      int32_t to, el_changes** changes, el_error* error);
/* Inside the shape every material from_to[2i] becomes from_to[2i + 1] at once, the others
 * stay (C++ relabel with a MaterialMap; a later pair for one material wins). */
EL_API el_status el_landscape_relabel(el_landscape* landscape, const el_shape* shape,
                                      const int32_t* from_to, size_t pair_count,
                                      el_changes** changes, el_error* error);

/* Queries: a point or box corner beyond the bound is EL_COORDINATE_OUT_OF_RANGE. */
EL_API el_status el_landscape_material_at(const el_landscape* landscape, const el_point* p,
                                          uint8_t* material, el_error* error);
EL_API el_status el_landscape_crossings(const el_landscape* landscape, const el_point* from,
                                        const el_point* to, el_crossings** out, el_error* error);
/* *hit = 1 and *crossing filled when the ray enters a solid material, else *hit = 0. */
EL_API el_status el_landscape_raycast(const el_landscape* landscape, const el_point* from,
                                      const el_point* to, int32_t* hit, el_crossing* crossing,
                                      el_error* error);
/* The solid materials whose interiors meet the box's (or shape's), ascending, into
 * materials[0 .. *count - 1] (at most 255). */
EL_API el_status el_landscape_overlaps_box(const el_landscape* landscape, const el_box* box,
                                           uint8_t materials[256], size_t* count, el_error* error);
EL_API el_status el_landscape_overlaps_shape(const el_landscape* landscape, const el_shape* shape,
                                             uint8_t materials[256], size_t* count,
                                             el_error* error);
/* Every polygon whose bounding box meets the closed box, cell by cell in tree order. */
EL_API el_status el_landscape_polygons_in(const el_landscape* landscape, const el_box* box,
                                          el_polygons** out, el_error* error);
/* The boxes of the cells (the tree's leaves, empty ones too) that meet the closed box, in tree
 * order, copied into buf (copy_to: EL_BUFFER_TOO_SMALL with *needed set when cap is less; the
 * world's cells number el_stats.cells). */
EL_API el_status el_landscape_cells_in(const el_landscape* landscape, const el_box* box,
                                       el_box* buf, size_t cap, size_t* needed, el_error* error);
EL_API el_status el_landscape_twice_area(const el_landscape* landscape, int32_t material,
                                         el_int128* out, el_error* error);
EL_API el_status el_landscape_world(const el_landscape* landscape, el_box* out, el_error* error);

typedef struct el_stats {
  uint32_t struct_size;
  uint32_t reserved;
  uint64_t polygons, vertices, cells, depth, bytes;
} el_stats;
EL_API void el_stats_init(el_stats* stats);
EL_API el_status el_landscape_stats(const el_landscape* landscape, el_stats* out, el_error* error);

/* The 64-bit state hash: equal states, equal hashes, on every platform. */
EL_API el_status el_landscape_state_hash(const el_landscape* landscape, uint64_t* out,
                                         el_error* error);
/* Every invariant over the whole world; *problems = one line per problem (empty: valid). */
EL_API el_status el_landscape_check(const el_landscape* landscape, el_bytes** problems,
                                    el_error* error);
EL_API el_status el_landscape_set_checked(el_landscape* landscape, int32_t on, el_error* error);
/* The edit log (README.md, "Landscape edit logs"): start, stop, and the lines so far. */
EL_API el_status el_landscape_start_log(el_landscape* landscape, el_error* error);
EL_API el_status el_landscape_stop_log(el_landscape* landscape, el_error* error);
EL_API el_status el_landscape_log(const el_landscape* landscape, el_bytes** out, el_error* error);

/* The versioned, checksummed binary save; load reads untrusted bytes (EL_LOAD_ERROR with the
 * byte offset, or EL_LIMIT_EXCEEDED) with the limits of `config` (NULL: the defaults; its
 * other fields are not read). */
EL_API el_status el_landscape_save(const el_landscape* landscape, el_bytes** out, el_error* error);
EL_API el_status el_landscape_load(const uint8_t* data, size_t size,
                                   const el_landscape_config* config, el_landscape** out,
                                   el_error* error);

/* ---- edit logs --------------------------------------------------------------------------------
 */

typedef struct el_replay el_replay; /* a replayed edit log (C++ log::LandscapeReplay) */

/* Replays a landscape edit log (README.md "Landscape edit logs": what el_landscape_log records
 * and `edgeland replay` reads) as `edgeland replay` does: the world of its world line, in the
 * default configuration, then its edits in order up to the first line that cannot be read or the
 * first edit the landscape refuses; the edits before it are kept. The text is untrusted: a bad
 * log is a replay that stopped (el_replay_stopped), not a failure of this call, which fails only
 * for a NULL argument or memory. The replayed landscape records its own log from the start, so
 * its el_landscape_log replays to it bit for bit. */
EL_API el_status el_replay_log(const char* text, size_t size, el_replay** out, el_error* error);
EL_API void el_replay_destroy(el_replay* replay);
/* A snapshot of the replayed landscape (O(1)); EL_LOAD_ERROR (index: the line) when the log has
 * no good world line, and so no world. */
EL_API el_status el_replay_landscape(const el_replay* replay, el_landscape** out, el_error* error);
/* The edits applied (0 for NULL). */
EL_API size_t el_replay_edits(const el_replay* replay);
/* Why the replay stopped before the log's end, in `error`: EL_OK when it did not; EL_LOAD_ERROR
 * for a line that cannot be read or an edit the landscape refused (index: the line, 1-based; the
 * message "line N: ..."), EL_INTERNAL for a bug of edgeland's that the edit met. */
EL_API el_status el_replay_stopped(const el_replay* replay, el_error* error);
/* The JSON object `edgeland replay` prints for the log, on one line (io/.../landscape_replay.hpp:
 * edits, polygons, vertices, cells, depth, area, state_hash, edits_per_second, and
 * stopped_at_line and error when it stopped). */
EL_API el_status el_replay_report(const el_replay* replay, el_bytes** out, el_error* error);

/* ---- results ----------------------------------------------------------------------------------
 */

/* A change set: ids removed (ascending), polygons added (el_polygons, ascending id; borrowed:
 * it lives as long as the change set and needs no destroy), cells rebuilt, area per material. */
EL_API void el_changes_destroy(el_changes* changes);
EL_API const uint64_t* el_changes_removed(const el_changes* changes, size_t* count);
EL_API el_status el_changes_copy_removed(const el_changes* changes, uint64_t* buf, size_t cap,
                                         size_t* needed);
EL_API const el_polygons* el_changes_added(const el_changes* changes);
EL_API const el_box* el_changes_cells(const el_changes* changes, size_t* count);
EL_API el_status el_changes_copy_cells(const el_changes* changes, el_box* buf, size_t cap,
                                       size_t* needed);
EL_API const el_area_delta* el_changes_area_delta(const el_changes* changes, size_t* count);
EL_API el_status el_changes_copy_area_delta(const el_changes* changes, el_area_delta* buf,
                                            size_t cap, size_t* needed);

/* Polygons as parallel arrays: polygon i has ids[i], materials[i], cells[i] (its cell's box)
 * and the points offsets[i] .. offsets[i + 1] - 1 (counter-clockwise; offsets has count + 1
 * entries). Destroying a borrowed el_polygons (from el_changes_added) does nothing. */
EL_API void el_polygons_destroy(el_polygons* polygons);
EL_API size_t el_polygons_count(const el_polygons* polygons);
EL_API const uint64_t* el_polygons_ids(const el_polygons* polygons, size_t* count);
EL_API el_status el_polygons_copy_ids(const el_polygons* polygons, uint64_t* buf, size_t cap,
                                      size_t* needed);
EL_API const uint8_t* el_polygons_materials(const el_polygons* polygons, size_t* count);
EL_API el_status el_polygons_copy_materials(const el_polygons* polygons, uint8_t* buf, size_t cap,
                                            size_t* needed);
EL_API const el_box* el_polygons_cells(const el_polygons* polygons, size_t* count);
EL_API el_status el_polygons_copy_cells(const el_polygons* polygons, el_box* buf, size_t cap,
                                        size_t* needed);
EL_API const uint32_t* el_polygons_offsets(const el_polygons* polygons, size_t* count);
EL_API el_status el_polygons_copy_offsets(const el_polygons* polygons, uint32_t* buf, size_t cap,
                                          size_t* needed);
EL_API const el_point* el_polygons_points(const el_polygons* polygons, size_t* count);
EL_API el_status el_polygons_copy_points(const el_polygons* polygons, el_point* buf, size_t cap,
                                         size_t* needed);

EL_API void el_crossings_destroy(el_crossings* crossings);
EL_API const el_crossing* el_crossings_data(const el_crossings* crossings, size_t* count);
EL_API el_status el_crossings_copy(const el_crossings* crossings, el_crossing* buf, size_t cap,
                                   size_t* needed);

EL_API void el_bytes_destroy(el_bytes* bytes);
EL_API const uint8_t* el_bytes_data(const el_bytes* bytes, size_t* size);
EL_API el_status el_bytes_copy(const el_bytes* bytes, uint8_t* buf, size_t cap, size_t* needed);

/* ---- the game layer (game/README.md) ---------------------------------------------------------
 * Bound as it stands: the surface tracker, the island tracker, detach, meshes and convex pieces,
 * each fed every edit's change set in order (also those detach returns). */

typedef struct el_surface_tracker el_surface_tracker; /* C++ SurfaceTracker */
typedef struct el_island_tracker el_island_tracker;   /* C++ IslandTracker */
typedef struct el_chains el_chains;                   /* surface chains and chain ids removed */
typedef struct el_islands el_islands;                 /* debris islands */
typedef struct el_detached el_detached;               /* an island taken out (C++ DetachedIsland) */
typedef struct el_meshes el_meshes;                   /* triangle meshes and mesh ids dropped */

enum { EL_SURFACE_BORDER_WALL = 1 }; /* el_physics_materials.flags */

/* C++ PhysicsMaterials and SurfaceOptions: solid[m] != 0 when material m collides (0 never
 * does), anchored[m] != 0 when it never falls; EL_SURFACE_BORDER_WALL makes the world border a
 * wall around the non-solid parts. Defaults (el_physics_materials_init): every material but 0
 * solid, none anchored, no wall. */
typedef struct el_physics_materials {
  uint32_t struct_size;
  uint32_t flags;
  uint8_t solid[256];
  uint8_t anchored[256];
} el_physics_materials;
EL_API void el_physics_materials_init(el_physics_materials* materials);

/* One surface chain (C++ SurfaceChain) beside its points: the id, whether it is closed, its
 * cell, its ghost vertices (the surface points before its first and after its last point). */
typedef struct el_chain_info {
  el_box cell;
  el_point ghost_prev, ghost_next;
  uint64_t id;
  uint32_t closed;
  uint32_t reserved;
} el_chain_info;

/* The chains kept in step with a landscape: create with every chain of the world (ids from 1),
 * then update with each edit's change set, in order (resync after any other change: a restored
 * snapshot, a load). An update's el_chains holds the ids removed and the chains added. */
EL_API el_status el_surface_tracker_create(const el_landscape* landscape,
                                           const el_physics_materials* materials,
                                           el_surface_tracker** out, el_error* error);
EL_API void el_surface_tracker_destroy(el_surface_tracker* tracker);
EL_API el_status el_surface_tracker_update(el_surface_tracker* tracker,
                                           const el_landscape* landscape, const el_changes* changes,
                                           el_chains** update, el_error* error);
EL_API el_status el_surface_tracker_resync(el_surface_tracker* tracker,
                                           const el_landscape* landscape, el_chains** update,
                                           el_error* error);
/* Every chain the tracker holds now, by ascending id (none removed). */
EL_API el_status el_surface_tracker_chains(const el_surface_tracker* tracker, el_chains** all,
                                           el_error* error);

/* Chains as arrays: chain i has info[i] and the points offsets[i] .. offsets[i + 1] - 1, with
 * solid on their left; materials[k] is the solid material left of the segment from point k to
 * the next (a closed chain's last point to its first; 0 after an open chain's last point and
 * along a border wall). */
EL_API void el_chains_destroy(el_chains* chains);
EL_API const uint64_t* el_chains_removed(const el_chains* chains, size_t* count);
EL_API el_status el_chains_copy_removed(const el_chains* chains, uint64_t* buf, size_t cap,
                                        size_t* needed);
EL_API const el_chain_info* el_chains_info(const el_chains* chains, size_t* count);
EL_API el_status el_chains_copy_info(const el_chains* chains, el_chain_info* buf, size_t cap,
                                     size_t* needed);
EL_API const uint32_t* el_chains_offsets(const el_chains* chains, size_t* count);
EL_API el_status el_chains_copy_offsets(const el_chains* chains, uint32_t* buf, size_t cap,
                                        size_t* needed);
EL_API const el_point* el_chains_points(const el_chains* chains, size_t* count);
EL_API el_status el_chains_copy_points(const el_chains* chains, el_point* buf, size_t cap,
                                       size_t* needed);
EL_API const uint8_t* el_chains_materials(const el_chains* chains, size_t* count);
EL_API el_status el_chains_copy_materials(const el_chains* chains, uint8_t* buf, size_t cap,
                                          size_t* needed);

/* One debris island (C++ Island): its bounds, exact twice area, and its pieces
 * first_piece .. first_piece + piece_count - 1 of the islands' pieces (landscape polygons). */
typedef struct el_island_info {
  el_box bounds;
  el_int128 twice_area;
  uint32_t first_piece;
  uint32_t piece_count;
} el_island_info;

/* Islands kept in step: an update returns the islands that exist now and did not before. */
EL_API el_status el_island_tracker_create(const el_landscape* landscape,
                                          const el_physics_materials* materials,
                                          el_island_tracker** out, el_error* error);
EL_API void el_island_tracker_destroy(el_island_tracker* tracker);
EL_API el_status el_island_tracker_update(el_island_tracker* tracker, const el_landscape* landscape,
                                          const el_changes* changes, el_islands** found,
                                          el_error* error);
EL_API el_status el_island_tracker_resync(el_island_tracker* tracker, const el_landscape* landscape,
                                          el_islands** found, el_error* error);
/* Every island of the landscape last seen (`landscape` must be it). */
EL_API el_status el_island_tracker_islands(const el_island_tracker* tracker,
                                           const el_landscape* landscape, el_islands** all,
                                           el_error* error);

EL_API void el_islands_destroy(el_islands* islands);
EL_API size_t el_islands_count(const el_islands* islands);
EL_API const el_island_info* el_islands_info(const el_islands* islands, size_t* count);
EL_API el_status el_islands_copy_info(const el_islands* islands, el_island_info* buf, size_t cap,
                                      size_t* needed);
/* All islands' pieces (borrowed, as el_changes_added). */
EL_API const el_polygons* el_islands_pieces(const el_islands* islands);

/* An island taken out: twice its area and its centroid (x_num / den, y_num / den), exact. */
typedef struct el_detached_info {
  el_int128 twice_area;
  el_int128 centroid_x_num, centroid_y_num, centroid_den;
} el_detached_info;

/* Removes island `index` of `islands` from the landscape as one edit (EL_STALE_ISLAND when the
 * landscape changed under it: the tracker reports it again after the next update). Pass the
 * returned change set (el_detached_changes) to every tracker, as any edit's. */
EL_API el_status el_detach(el_landscape* landscape, const el_islands* islands, size_t index,
                           el_detached** out, el_error* error);
EL_API void el_detached_destroy(el_detached* detached);
EL_API el_status el_detached_summary(const el_detached* detached, el_detached_info* out,
                                     el_error* error);
/* The edit's change set and the island's region, each material's maximal polygons (ids 0);
 * both borrowed. */
EL_API const el_changes* el_detached_changes(const el_detached* detached);
EL_API const el_polygons* el_detached_regions(const el_detached* detached);

/* Triangle meshes per polygon id: an edit's (from its change set alone: the meshes to drop and
 * those to build) or the whole world's. Mesh i is polygon i of el_meshes_polygons (id,
 * material, its own vertices) and the triangles triangle_offsets[i] .. triangle_offsets[i + 1]
 * - 1, three vertex indices each, counter-clockwise. */
EL_API el_status el_mesh_update(const el_changes* changes, el_meshes** out, el_error* error);
EL_API el_status el_all_meshes(const el_landscape* landscape, el_meshes** out, el_error* error);
EL_API void el_meshes_destroy(el_meshes* meshes);
EL_API const uint64_t* el_meshes_dropped(const el_meshes* meshes, size_t* count);
EL_API el_status el_meshes_copy_dropped(const el_meshes* meshes, uint64_t* buf, size_t cap,
                                        size_t* needed);
EL_API const el_polygons* el_meshes_polygons(const el_meshes* meshes);
EL_API const uint32_t* el_meshes_triangle_offsets(const el_meshes* meshes, size_t* count);
EL_API el_status el_meshes_copy_triangle_offsets(const el_meshes* meshes, uint32_t* buf, size_t cap,
                                                 size_t* needed);
EL_API const uint32_t* el_meshes_triangles(const el_meshes* meshes, size_t* count);
EL_API el_status el_meshes_copy_triangles(const el_meshes* meshes, uint32_t* buf, size_t cap,
                                          size_t* needed);

/* A valid polygon (the kernel's rules) as convex pieces of at most max_vertices (>= 3; Box2D's
 * is 8) vertices each, strictly convex and counter-clockwise, tiling it exactly. */
EL_API el_status el_convex_pieces(const el_point* points, size_t count, uint32_t max_vertices,
                                  el_polygons** out, el_error* error);

/* ---- the game driver (game/include/edgeland/game/game_driver.hpp) ----------------------------
 * What a game uses: one driver owns a landscape and everything derived from it. Each frame, the
 * frame's edits (an el_edits batch) go in as one batch and an el_game_update comes out: the
 * change set, the collision chains to remove and add (with ghost vertices), the render meshes
 * to drop and build, and the islands that broke off as debris (regions, convex pieces, meshes,
 * exact area and centroid); el_game_driver_buried asks whether a fill buried a body.
 *
 * Errors: an edit's typed error (EL_INVALID_INPUT, EL_INVALID_MATERIAL, EL_LIMIT_EXCEEDED, ...)
 * leaves the driver and its landscape exactly as they were. EL_OUT_OF_MEMORY from apply or reset
 * leaves the driver as the C++ one does: reset it (el_game_driver_reset) before the next apply. */

typedef struct el_edits el_edits;             /* a frame's edits, in order (C++ Edit) */
typedef struct el_game_driver el_game_driver; /* C++ GameDriver */
typedef struct el_game_update el_game_update; /* C++ GameUpdate */

/* A batch of edits, each holding its own copy of the shape: the materials are checked when an
 * edit is added (EL_INVALID_MATERIAL, the batch unchanged). */
EL_API el_status el_edits_create(el_edits** out, el_error* error);
EL_API void el_edits_destroy(el_edits* edits);
EL_API void el_edits_clear(el_edits* edits);
EL_API size_t el_edits_count(const el_edits* edits);
EL_API el_status el_edits_carve(el_edits* edits, const el_shape* shape, el_error* error);
EL_API el_status el_edits_fill(el_edits* edits, const el_shape* shape, int32_t material,
                               el_error* error);
EL_API el_status el_edits_fill_empty(el_edits* edits, const el_shape* shape, int32_t material,
                                     el_error* error);
EL_API el_status el_edits_replace(el_edits* edits, const el_shape* shape, int32_t from, int32_t to,
                                  el_error* error);
EL_API el_status el_edits_relabel(el_edits* edits, const el_shape* shape, const int32_t* from_to,
                                  size_t pair_count, el_error* error);

enum {
  EL_GAME_MESHES = 1,
  EL_GAME_DEBRIS = 2,
  EL_GAME_BORDER_WALL = 4
}; /* el_game_options.flags */

/* C++ GameOptions. Defaults (el_game_options_init): EL_GAME_MESHES | EL_GAME_DEBRIS, every
 * material but 0 solid, none anchored, convex pieces of at most 8 vertices (3 or more), a debris
 * budget of 8192 island vertices per update, no island waiting more than 3 updates. */
typedef struct el_game_options {
  uint32_t struct_size;
  uint32_t flags;
  uint64_t debris_budget;
  uint32_t max_piece_vertices;
  uint32_t max_debris_wait;
  uint8_t solid[256];
  uint8_t anchored[256];
} el_game_options;
EL_API void el_game_options_init(el_game_options* options);

/* A driver over a snapshot of `world` (O(1); the caller's landscape stays its own). Islands
 * already in the world wait in the debris queue: the first update detaches them. */
EL_API el_status el_game_driver_create(const el_landscape* world, const el_game_options* options,
                                       el_game_driver** out, el_error* error);
EL_API void el_game_driver_destroy(el_game_driver* driver);
/* The batch's edits in order, as one; then the chains, meshes and islands kept in step and
 * debris detached within the budget. `edits` NULL or empty: only the debris queue moves.
 * `update` may be NULL (not wanted); else *update gets a new update. */
EL_API el_status el_game_driver_apply(el_game_driver* driver, const el_edits* edits,
                                      el_game_update** update, el_error* error);
/* The landscape replaced by a snapshot of `world` (an undo to a snapshot, a load): the update
 * names exactly the cells whose polygons differ from the last seen. */
EL_API el_status el_game_driver_reset(el_game_driver* driver, const el_landscape* world,
                                      el_game_update** update, el_error* error);
/* *buried = 1 when the last update's fills buried a body whose bounding box is `box`. */
EL_API el_status el_game_driver_buried(const el_game_driver* driver, const el_box* box,
                                       int32_t* buried, el_error* error);
/* A snapshot of the driver's landscape (O(1)): queries, save, state hash. */
EL_API el_status el_game_driver_landscape(const el_game_driver* driver, el_landscape** out,
                                          el_error* error);
/* Every chain now, by ascending id (what the updates so far add up to; none removed). */
EL_API el_status el_game_driver_chains(const el_game_driver* driver, el_chains** all,
                                       el_error* error);
EL_API size_t el_game_driver_debris_waiting(const el_game_driver* driver);

/* One debris body (C++ Debris): its bounds, exact twice area and centroid (x_num / den,
 * y_num / den); its region polygons (maximal, per material, ascending material) are
 * first_region .. first_region + region_count - 1 of el_game_update_debris_regions, each
 * region polygon's mesh the same index of el_game_update_debris_meshes (when EL_GAME_MESHES),
 * and its convex pieces (one fixture each, the material in el_polygons_materials) first_piece ..
 * of el_game_update_debris_pieces. */
typedef struct el_debris_info {
  el_box bounds;
  el_int128 twice_area;
  el_int128 centroid_x_num, centroid_y_num, centroid_den;
  uint32_t first_region, region_count;
  uint32_t first_piece, piece_count;
} el_debris_info;

/* What one update did (C++ GameWork) and the islands still waiting. */
typedef struct el_game_work {
  uint32_t struct_size;
  uint32_t reserved;
  uint64_t cells_scanned, boundary_passes, cells_traced, islands_found, islands_detached;
  uint64_t debris_waiting;
} el_game_work;
EL_API void el_game_work_init(el_game_work* work);

/* The parts of an update, borrowed (they live as long as the update and need no destroy): the
 * change set (every polygon the edits and the detaches removed and added), the chains (ids
 * removed, chains added with their ghosts), the meshes (ids dropped, meshes built; empty without
 * EL_GAME_MESHES), the debris. */
EL_API void el_game_update_destroy(el_game_update* update);
EL_API const el_changes* el_game_update_changes(const el_game_update* update);
EL_API const el_chains* el_game_update_chains(const el_game_update* update);
EL_API const el_meshes* el_game_update_meshes(const el_game_update* update);
EL_API const el_debris_info* el_game_update_debris(const el_game_update* update, size_t* count);
EL_API el_status el_game_update_copy_debris(const el_game_update* update, el_debris_info* buf,
                                            size_t cap, size_t* needed);
EL_API const el_polygons* el_game_update_debris_regions(const el_game_update* update);
EL_API const el_meshes* el_game_update_debris_meshes(const el_game_update* update);
EL_API const el_polygons* el_game_update_debris_pieces(const el_game_update* update);
EL_API el_status el_game_update_work(const el_game_update* update, el_game_work* out,
                                     el_error* error);

/* ---- layout ------------------------------------------------------------------------------------
 * The same on every target: 8-byte fields first, explicit padding, no pointers or size_t in
 * structs (i686's 4-byte alignment of int64_t would move a field after a 4-byte one). C99 has
 * no _Static_assert, hence the negative-array form. */
#define EL_LAYOUT_ASSERT(name, cond) typedef char el_layout_##name[(cond) ? 1 : -1]
EL_LAYOUT_ASSERT(point, sizeof(el_point) == 16);
EL_LAYOUT_ASSERT(box, sizeof(el_box) == 32 && offsetof(el_box, max) == 16);
EL_LAYOUT_ASSERT(int128, sizeof(el_int128) == 24 && offsetof(el_int128, approx) == 16);
EL_LAYOUT_ASSERT(crossing, sizeof(el_crossing) == 168 && offsetof(el_crossing, rounded) == 120 &&
                               offsetof(el_crossing, polygon) == 152 &&
                               offsetof(el_crossing, edge) == 160 &&
                               offsetof(el_crossing, after) == 165);
EL_LAYOUT_ASSERT(area_delta,
                 sizeof(el_area_delta) == 32 && offsetof(el_area_delta, material) == 24);
EL_LAYOUT_ASSERT(error, sizeof(el_error) == 328 && offsetof(el_error, index) == 16 &&
                            offsetof(el_error, where) == 56 && offsetof(el_error, message) == 72);
EL_LAYOUT_ASSERT(config, sizeof(el_landscape_config) == 56 &&
                             offsetof(el_landscape_config, min_cell_size) == 16 &&
                             offsetof(el_landscape_config, max_vertices) == 32);
EL_LAYOUT_ASSERT(stats, sizeof(el_stats) == 48 && offsetof(el_stats, polygons) == 8);
EL_LAYOUT_ASSERT(physics_materials, sizeof(el_physics_materials) == 520 &&
                                        offsetof(el_physics_materials, anchored) == 264);
EL_LAYOUT_ASSERT(chain_info, sizeof(el_chain_info) == 80 && offsetof(el_chain_info, id) == 64 &&
                                 offsetof(el_chain_info, closed) == 72);
EL_LAYOUT_ASSERT(island_info,
                 sizeof(el_island_info) == 64 && offsetof(el_island_info, first_piece) == 56);
EL_LAYOUT_ASSERT(detached_info, sizeof(el_detached_info) == 96);
EL_LAYOUT_ASSERT(game_options, sizeof(el_game_options) == 536 &&
                                   offsetof(el_game_options, max_piece_vertices) == 16 &&
                                   offsetof(el_game_options, solid) == 24 &&
                                   offsetof(el_game_options, anchored) == 280);
EL_LAYOUT_ASSERT(debris_info, sizeof(el_debris_info) == 144 &&
                                  offsetof(el_debris_info, centroid_den) == 104 &&
                                  offsetof(el_debris_info, first_region) == 128 &&
                                  offsetof(el_debris_info, piece_count) == 140);
EL_LAYOUT_ASSERT(game_work,
                 sizeof(el_game_work) == 56 && offsetof(el_game_work, debris_waiting) == 48);

#ifdef __cplusplus
}
#endif

#endif /* EDGELAND_EDGELAND_H */
