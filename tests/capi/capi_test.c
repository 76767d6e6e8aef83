/* The C API from C99 (edgeland.h): every call's status and results, the errors' fields, the
 * strong guarantee across the border, snapshots, save/load, the OGC import, log replay, copy_to,
 * NULL handles; the game driver's part is driver_test.c. Built twice, against the shared and the
 * static library, and a third time by mingw-w64 as a Windows program against the DLL
 * (scripts/test_capi_windows.sh).
 * Prints "capi: N checks passed" and exits 0, or names the first failed check and exits 1. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "edgeland/edgeland.h"

int checks = 0;

static uint64_t hash_of(const el_landscape* world) {
  uint64_t h = 0;
  OK(el_landscape_state_hash(world, &h, NULL));
  return h;
}

static el_shape* square(int64_t x0, int64_t y0, int64_t side) {
  const int64_t xy[8] = {x0, y0, x0 + side, y0, x0 + side, y0 + side, x0, y0 + side};
  const uint32_t offsets[2] = {0, 4};
  el_shape* shape = NULL;
  OK(el_shape_create(xy, offsets, 1, &shape, NULL));
  return shape;
}

static el_landscape* new_world(void) {
  const el_box box = {{0, 0}, {1024, 512}};
  el_landscape_config config;
  el_landscape* world = NULL;
  el_landscape_config_init(&config);
  config.flags = EL_LANDSCAPE_CHECKED;
  OK(el_landscape_create(&box, 1, &config, &world, NULL));
  return world;
}

static void test_version(void) {
  CHECK(el_version() == EL_VERSION);
  OK(el_check_version(EL_VERSION));
  CHECK(el_check_version(EL_VERSION + (1u << 16)) == EL_VERSION_MISMATCH);
  CHECK(el_check_version(EL_VERSION + (1u << 8)) == EL_VERSION_MISMATCH);
  CHECK(strcmp(el_status_name(EL_INVALID_MATERIAL), "EL_INVALID_MATERIAL") == 0);
  CHECK(strcmp(el_status_name(EL_DELTA_ERROR), "EL_DELTA_ERROR") == 0);
  CHECK(strcmp(el_status_name(EL_DELTA_MISMATCH), "EL_DELTA_MISMATCH") == 0);
  CHECK(strcmp(el_status_name(EL_INVALID_PATH), "EL_INVALID_PATH") == 0);
  CHECK(strcmp(el_status_name(EL_REGION_NOT_LOADED), "EL_REGION_NOT_LOADED") == 0);
  CHECK(strcmp(el_status_name(EL_UNKNOWN_POLYGON), "EL_UNKNOWN_POLYGON") == 0);
  CHECK(strcmp(el_status_name(12345), "EL_UNKNOWN") == 0);
}

/* An edit's change set: what went, what came, in which cells, and the exact areas. */
static void test_edit_and_changes(void) {
  el_landscape* world = new_world();
  el_shape* hole = NULL;
  el_changes* changes = NULL;
  const el_point center = {512, 256};
  el_int128 empty, rock;
  size_t removed = 0, cells = 0, deltas = 0, i;
  const el_area_delta* delta;
  const el_polygons* added;
  int64_t sum_lo = 0;

  OK(el_shape_circle(&center, 100, &hole, NULL));
  OK(el_landscape_carve(world, hole, &changes, NULL));
  el_changes_removed(changes, &removed);
  el_changes_cells(changes, &cells);
  added = el_changes_added(changes);
  CHECK(removed >= 1 && cells >= 1 && el_polygons_count(added) >= 1);
  delta = el_changes_area_delta(changes, &deltas);
  CHECK(deltas == 2);
  for (i = 0; i < deltas; ++i) sum_lo += (int64_t)delta[i].twice_area.lo;
  CHECK(sum_lo == 0); /* the changes sum to zero over all materials */
  CHECK(delta[0].material == 0 && delta[0].twice_area.hi == 0 && delta[0].twice_area.approx > 0);
  OK(el_landscape_twice_area(world, 0, &empty, NULL));
  OK(el_landscape_twice_area(world, 1, &rock, NULL));
  CHECK(empty.lo == delta[0].twice_area.lo);
  CHECK(rock.lo + empty.lo == 2u * 1024u * 512u && rock.hi == 0);
  CHECK(rock.approx == (double)rock.lo);
  el_polygons_destroy((el_polygons*)added); /* borrowed: a no-op */
  CHECK(el_polygons_count(el_changes_added(changes)) >= 1);
  el_changes_destroy(changes);
  el_shape_destroy(hole);
  el_landscape_destroy(world);
}

/* A refused edit returns its typed error with its data and leaves the world as it was. */
static void test_errors_keep_the_world(void) {
  el_landscape* world = new_world();
  const uint64_t before = hash_of(world);
  const int64_t bowtie[8] = {0, 0, 10, 10, 10, 0, 0, 10};
  const int64_t far[6] = {0, 0, 3000000000LL, 0, 0, 10};
  const uint32_t four[2] = {0, 4}, three[2] = {0, 3};
  el_shape* shape = NULL;
  el_shape* ok = square(10, 10, 20);
  el_changes* changes = (el_changes*)&checks; /* must stay untouched on failure */
  el_error error;
  el_error_init(&error);

  CHECK(el_shape_create(bowtie, four, 1, &shape, &error) == EL_INVALID_INPUT);
  CHECK(shape == NULL && error.status == EL_INVALID_INPUT);
  CHECK(error.kind == EL_RULE_SELF_INTERSECTION && error.operand == EL_OPERAND_CLIP);
  CHECK(error.index == 0 && error.vertex == 0 && strstr(error.message, "self-intersection"));

  CHECK(el_shape_create(far, three, 1, &shape, &error) == EL_COORDINATE_OUT_OF_RANGE);
  CHECK(error.vertex == 1 && error.where.x == 3000000000LL);

  CHECK(el_landscape_fill(world, ok, 300, &changes, &error) == EL_INVALID_MATERIAL);
  CHECK(error.value == 300 && error.limit == 255 && changes == (el_changes*)&checks);
  CHECK(el_landscape_replace(world, ok, 1, -1, NULL, &error) == EL_INVALID_MATERIAL);
  CHECK(error.value == -1);
  CHECK(hash_of(world) == before);

  { /* a shape over the limit of one edit's vertices */
    el_landscape_config config;
    el_landscape* small = NULL;
    const el_box box = {{0, 0}, {100, 100}};
    el_landscape_config_init(&config);
    config.max_shape_vertices = 3;
    OK(el_landscape_create(&box, 0, &config, &small, NULL));
    CHECK(el_landscape_fill(small, ok, 2, NULL, &error) == EL_LIMIT_EXCEEDED);
    CHECK(error.kind == EL_LIMIT_SHAPE_VERTICES && error.limit == 3 && error.value == 4);
    el_landscape_destroy(small);
  }
  { /* configuration errors */
    const el_box inverted = {{10, 0}, {0, 10}};
    el_landscape_config config;
    el_landscape* bad = NULL;
    CHECK(el_landscape_create(&inverted, 0, NULL, &bad, &error) == EL_INVALID_CONFIG);
    CHECK(error.kind == EL_SETTING_WORLD_EMPTY && bad == NULL);
    el_landscape_config_init(&config);
    config.edge_cap = 8;
    CHECK(el_landscape_create(&(el_box){{0, 0}, {10, 10}}, 0, &config, &bad, &error) ==
          EL_INVALID_CONFIG);
    CHECK(error.kind == EL_SETTING_EDGE_CAP);
    config.struct_size = sizeof config + 8; /* a newer header's struct */
    CHECK(el_landscape_create(&(el_box){{0, 0}, {10, 10}}, 0, &config, &bad, &error) ==
          EL_VERSION_MISMATCH);
  }
  { /* queries check their coordinates too */
    const el_point outside = {0, -3000000000LL};
    uint8_t m = 7;
    CHECK(el_landscape_material_at(world, &outside, &m, &error) == EL_COORDINATE_OUT_OF_RANGE);
    CHECK(m == 7 && error.operand == EL_OPERAND_QUERY);
  }
  CHECK(el_landscape_carve(NULL, ok, NULL, &error) == EL_NULL_ARGUMENT);
  CHECK(strstr(error.message, "landscape") != NULL);
  CHECK(el_landscape_carve(world, NULL, NULL, NULL) == EL_NULL_ARGUMENT);
  CHECK(hash_of(world) == before);
  el_shape_destroy(ok);
  el_landscape_destroy(world);
}

static void test_queries(void) {
  el_landscape* world = new_world();
  el_shape* pit = square(100, 100, 50);
  el_shape* ore = square(300, 100, 20);
  const el_point inside = {120, 120}, rock = {10, 10}, from = {120, 125}, to = {120, 400};
  const el_box box = {{90, 90}, {160, 160}};
  el_crossings* crossings = NULL;
  el_crossing hit;
  uint8_t materials[256];
  uint8_t m = 99;
  size_t count = 0;
  int32_t found = 0;
  const el_crossing* c;

  OK(el_landscape_carve(world, pit, NULL, NULL));
  OK(el_landscape_fill(world, ore, 3, NULL, NULL));
  OK(el_landscape_material_at(world, &inside, &m, NULL));
  CHECK(m == 0);
  OK(el_landscape_material_at(world, &rock, &m, NULL));
  CHECK(m == 1);

  OK(el_landscape_raycast(world, &from, &to, &found, &hit, NULL));
  CHECK(found == 1 && hit.rounded.x == 120 && hit.rounded.y == 150 && hit.after == 1);
  CHECK(hit.den.lo != 0 && hit.normal.y != 0);
  OK(el_landscape_crossings(world, &from, &to, &crossings, NULL));
  c = el_crossings_data(crossings, &count);
  CHECK(count == 1 && c[0].before == 0 && c[0].after == 1);
  el_crossings_destroy(crossings);

  OK(el_landscape_overlaps_box(world, &box, materials, &count, NULL));
  CHECK(count == 1 && materials[0] == 1);
  {
    const el_box wide = {{0, 0}, {400, 200}};
    OK(el_landscape_overlaps_box(world, &wide, materials, &count, NULL));
    CHECK(count == 2 && materials[0] == 1 && materials[1] == 3);
  }
  OK(el_landscape_overlaps_shape(world, pit, materials, &count, NULL));
  CHECK(count == 0);
  el_shape_destroy(pit);
  el_shape_destroy(ore);
  el_landscape_destroy(world);
}

/* Arrays out: pointers, and copies into a buffer that must be large enough. */
static void test_polygons_and_copy_to(void) {
  el_landscape* world = new_world();
  el_polygons* polygons = NULL;
  const el_box all = {{0, 0}, {1024, 512}};
  size_t n = 0, points = 0, needed = 0, offsets_n = 0;
  const uint32_t* offsets;
  el_point* copy;
  el_shape* ore = square(300, 100, 20);

  OK(el_landscape_fill(world, ore, 3, NULL, NULL));
  OK(el_landscape_polygons_in(world, &all, &polygons, NULL));
  n = el_polygons_count(polygons);
  CHECK(n >= 2);
  offsets = el_polygons_offsets(polygons, &offsets_n);
  el_polygons_points(polygons, &points);
  CHECK(offsets_n == n + 1 && offsets[0] == 0 && offsets[n] == points);
  CHECK(el_polygons_copy_points(polygons, NULL, 0, &needed) == EL_BUFFER_TOO_SMALL);
  CHECK(needed == points);
  copy = malloc(points * sizeof *copy);
  CHECK(el_polygons_copy_points(polygons, copy, points - 1, &needed) == EL_BUFFER_TOO_SMALL);
  OK(el_polygons_copy_points(polygons, copy, points, &needed));
  CHECK(memcmp(copy, el_polygons_points(polygons, NULL), points * sizeof *copy) == 0);
  free(copy);
  {
    size_t i;
    const uint8_t* materials = el_polygons_materials(polygons, NULL);
    const uint64_t* ids = el_polygons_ids(polygons, NULL);
    int ore_seen = 0;
    for (i = 0; i < n; ++i) {
      CHECK(ids[i] >= 1);
      if (materials[i] == 3) ore_seen = 1;
    }
    CHECK(ore_seen);
  }
  el_polygons_destroy(polygons);
  el_shape_destroy(ore);
  el_landscape_destroy(world);
}

/* A clone is a snapshot; save/load keeps the state hash; bad bytes are a LOAD_ERROR. */
static void test_snapshots_and_saves(void) {
  el_landscape* world = new_world();
  el_landscape* snapshot = NULL;
  el_landscape* loaded = NULL;
  el_shape* pit = square(100, 100, 50);
  el_bytes* save = NULL;
  const uint64_t before = hash_of(world);
  const uint8_t junk[5] = {1, 2, 3, 4, 5};
  uint8_t* copy;
  size_t size = 0, needed = 0;
  const uint8_t* data;
  el_error error;
  el_error_init(&error);

  OK(el_landscape_clone(world, &snapshot, NULL));
  OK(el_landscape_carve(world, pit, NULL, NULL));
  CHECK(hash_of(snapshot) == before && hash_of(world) != before);

  OK(el_landscape_save(world, &save, NULL));
  data = el_bytes_data(save, &size);
  CHECK(size > 16 && data != NULL);
  copy = malloc(size);
  OK(el_bytes_copy(save, copy, size, &needed));
  OK(el_landscape_load(copy, size, NULL, &loaded, NULL));
  CHECK(hash_of(loaded) == hash_of(world));
  el_landscape_destroy(loaded);
  loaded = NULL;
  copy[size / 2] ^= 0x40;
  CHECK(el_landscape_load(copy, size, NULL, &loaded, &error) == EL_LOAD_ERROR && loaded == NULL);
  CHECK(el_landscape_load(junk, sizeof junk, NULL, &loaded, &error) == EL_LOAD_ERROR);
  CHECK(error.index <= sizeof junk);
  free(copy);
  el_bytes_destroy(save);

  {
    el_bytes* problems = NULL;
    OK(el_landscape_check(world, &problems, NULL));
    el_bytes_data(problems, &size);
    CHECK(size == 0);
    el_bytes_destroy(problems);
  }
  el_shape_destroy(pit);
  el_landscape_destroy(snapshot);
  el_landscape_destroy(world);
}

/* relabel: two materials swapped at once; the log records it. */
static void test_relabel_and_log(void) {
  el_landscape* world = new_world();
  el_shape* ore = square(300, 100, 20);
  el_shape* all = square(0, 0, 512);
  const int32_t swap[4] = {1, 3, 3, 1};
  const int32_t bad[2] = {1, 256};
  const el_point in_ore = {310, 110}, in_rock = {10, 10};
  uint8_t m = 0;
  el_bytes* log = NULL;
  size_t size = 0;
  const uint8_t* text;

  OK(el_landscape_start_log(world, NULL));
  OK(el_landscape_fill(world, ore, 3, NULL, NULL));
  OK(el_landscape_relabel(world, all, swap, 2, NULL, NULL));
  OK(el_landscape_material_at(world, &in_ore, &m, NULL));
  CHECK(m == 1);
  OK(el_landscape_material_at(world, &in_rock, &m, NULL));
  CHECK(m == 3);
  CHECK(el_landscape_relabel(world, all, bad, 1, NULL, NULL) == EL_INVALID_MATERIAL);
  OK(el_landscape_log(world, &log, NULL));
  text = el_bytes_data(log, &size);
  CHECK(size > 0 && memcmp(text, "world 0 0 1024 512 1\n", 21) == 0);
  el_bytes_destroy(log);
  el_shape_destroy(ore);
  el_shape_destroy(all);
  el_landscape_destroy(world);
}

static void test_shape_builders(void) {
  const el_point c = {0, 0}, b = {100, 0};
  const el_box box = {{0, 0}, {10, 20}};
  el_shape* s = NULL;
  el_polygons* p = NULL;
  size_t n = 0;
  el_error error;
  el_error_init(&error);
  OK(el_shape_regular_polygon(&c, 50, 6, 0, 1, &s, NULL));
  OK(el_shape_polygons(s, &p, NULL));
  el_polygons_points(p, &n);
  CHECK(el_polygons_count(p) == 1 && n == 6);
  el_polygons_destroy(p);
  el_shape_destroy(s);
  OK(el_shape_capsule(&c, &b, 10, &s, NULL));
  el_shape_destroy(s);
  OK(el_shape_box(&box, &s, NULL));
  el_shape_destroy(s);
  OK(el_shape_rotated_box(&c, 10, 5, 1, 8, &s, NULL));
  el_shape_destroy(s);
  s = NULL;
  CHECK(el_shape_circle(&c, 0, &s, &error) == EL_ARGUMENT_OUT_OF_RANGE && s == NULL);
  CHECK(error.value == 0 && error.minimum == 1 && error.limit == (int64_t)1 << 33);
}

static el_polygons* polygons_of(const el_shape* shape) {
  el_polygons* p = NULL;
  OK(el_shape_polygons(shape, &p, NULL));
  return p;
}

/* The cells: every leaf, empty ones too, as many as the statistics count, tiling the world. */
static void test_cells(void) {
  el_landscape* world = new_world();
  el_shape* hole = NULL;
  const el_box all = {{0, 0}, {1024, 512}};
  el_box cells[512];
  el_stats stats;
  size_t needed = 0, i;
  int64_t area = 0;

  for (i = 0; i < 12; ++i) { /* enough edges to split the root */
    const el_point at = {40 + 80 * (int64_t)i, 100 + 25 * (int64_t)i};
    OK(el_shape_circle(&at, 30, &hole, NULL));
    OK(el_landscape_carve(world, hole, NULL, NULL));
    el_shape_destroy(hole);
  }
  el_stats_init(&stats);
  OK(el_landscape_stats(world, &stats, NULL));
  CHECK(el_landscape_cells_in(world, &all, NULL, 0, &needed, NULL) == EL_BUFFER_TOO_SMALL);
  CHECK(needed == stats.cells && needed > 1 && needed <= 512);
  OK(el_landscape_cells_in(world, &all, cells, 512, &needed, NULL));
  for (i = 0; i < needed; ++i) {
    CHECK(cells[i].min.x >= 0 && cells[i].max.x <= 1024 && cells[i].min.y >= 0 &&
          cells[i].max.y <= 512);
    area += (cells[i].max.x - cells[i].min.x) * (cells[i].max.y - cells[i].min.y);
  }
  CHECK(area == 1024 * 512);
  CHECK(el_landscape_cells_in(world, &all, cells, 512, NULL, NULL) == EL_NULL_ARGUMENT);
  el_landscape_destroy(world);
}

/* The shape el_shape_import makes of one polygon's rings (the exterior, then its holes). */
static el_shape* imported(const int64_t* xy, const uint32_t* ring_offsets, uint32_t rings) {
  const uint32_t polygon_rings[2] = {0, rings};
  el_shape* s = NULL;
  OK(el_shape_import(xy, ring_offsets, polygon_rings, 1, &s, NULL));
  return s;
}

static size_t polygon_count(const el_shape* s) {
  el_polygons* p = polygons_of(s);
  const size_t n = el_polygons_count(p);
  el_polygons_destroy(p);
  return n;
}

/* The OGC import: a bow tie becomes its two triangles, a clockwise ring its counter-clockwise
 * polygon, a square with a hole hole-free pieces of the right area, a ring of no area nothing;
 * a coordinate beyond the bound names its polygon and vertex. */
static void test_shape_import(void) {
  const int64_t bow_tie[] = {0, 0, 100, 100, 100, 0, 0, 100};
  const int64_t clockwise[] = {0, 0, 0, 10, 10, 10, 10, 0};
  const int64_t holed[] = {0, 0, 30, 0, 30, 30, 0, 30, 10, 10, 20, 10, 20, 20, 10, 20};
  const int64_t flat[] = {0, 0, 10, 0, 20, 0};
  const uint32_t one[] = {0, 4}, two[] = {0, 4, 8}, three[] = {0, 3};
  const int64_t far[] = {0, 0, 10, 0, 10, 10, 0, 0, (int64_t)1 << 40, 0, 0, 10};
  const uint32_t far_rings[] = {0, 3, 6}, far_polygons[] = {0, 1, 2}, descending[] = {0, 2, 1};
  const el_box box = {{0, 0}, {64, 64}};
  el_landscape* world = NULL;
  el_shape* s = imported(bow_tie, one, 1);
  el_polygons* p = NULL;
  el_int128 area;
  size_t n = 0;
  el_error error;
  el_error_init(&error);

  CHECK(polygon_count(s) == 2);
  el_shape_destroy(s);
  s = imported(clockwise, one, 1);
  p = polygons_of(s);
  CHECK(el_polygons_count(p) == 1 && el_polygons_points(p, &n)[1].x == 10 && n == 4);
  el_polygons_destroy(p);
  el_shape_destroy(s);
  OK(el_landscape_create(&box, 0, NULL, &world, NULL));
  s = imported(holed, two, 2);
  CHECK(polygon_count(s) >= 2);
  OK(el_landscape_fill(world, s, 2, NULL, NULL));
  OK(el_landscape_twice_area(world, 2, &area, NULL));
  CHECK(area.lo == 2 * (900 - 100) && area.hi == 0);
  el_shape_destroy(s);
  s = imported(flat, three, 1);
  CHECK(polygon_count(s) == 0);
  el_shape_destroy(s);
  s = NULL;
  CHECK(el_shape_import(far, far_rings, far_polygons, 2, &s, &error) ==
            EL_COORDINATE_OUT_OF_RANGE &&
        s == NULL);
  CHECK(error.operand == EL_OPERAND_RINGS && error.index == 1 && error.vertex == 1);
  CHECK(el_shape_import(far, far_rings, descending, 2, &s, NULL) == EL_INVALID_ARGUMENT);
  CHECK(el_shape_import(far, far_rings, NULL, 1, &s, NULL) == EL_NULL_ARGUMENT && s == NULL);
  el_landscape_destroy(world);
}

/* text contains what, as a C string. */
static int contains(const el_bytes* bytes, const char* what) {
  size_t size = 0, i, n = strlen(what);
  const uint8_t* text = el_bytes_data(bytes, &size);
  for (i = 0; i + n <= size; ++i) {
    if (memcmp(text + i, what, n) == 0) return 1;
  }
  return 0;
}

static el_bytes* report_of(const el_replay* replay) {
  el_bytes* report = NULL;
  OK(el_replay_report(replay, &report, NULL));
  return report;
}

/* A recorded log replays to the same state and records itself again, byte for byte. */
static void test_replay_of_a_recorded_log(el_landscape* world, el_bytes* log) {
  size_t size = 0, again_size = 0;
  const char* text = (const char*)el_bytes_data(log, &size);
  el_replay* replay = NULL;
  el_landscape* replayed = NULL;
  el_bytes *again = NULL, *report = NULL;
  char hash[40];

  OK(el_replay_log(text, size, &replay, NULL));
  OK(el_replay_stopped(replay, NULL));
  CHECK(el_replay_edits(replay) == 2);
  OK(el_replay_landscape(replay, &replayed, NULL));
  CHECK(hash_of(replayed) == hash_of(world));
  OK(el_landscape_log(replayed, &again, NULL));
  CHECK(memcmp(el_bytes_data(again, &again_size), text, size) == 0 && again_size == size);
  report = report_of(replay);
  sprintf(hash, "\"state_hash\":\"%016llx\"", (unsigned long long)hash_of(world));
  CHECK(contains(report, "{\"edits\":2,") && contains(report, hash));
  CHECK(!contains(report, "stopped_at_line"));
  el_bytes_destroy(report);
  el_bytes_destroy(again);
  el_landscape_destroy(replayed);
  el_replay_destroy(replay);
}

/* A bad line stops the replay there, the edits before it kept; a log without a world line has
 * no landscape. */
static void test_replay_that_stops(el_landscape* world, el_bytes* log) {
  const char* no_world = "carve POLYGON((0 0,1 0,1 1,0 1))\n";
  char text[4096];
  size_t size = 0;
  el_replay* replay = NULL;
  el_landscape* replayed = NULL;
  el_bytes* report = NULL;
  const uint8_t* recorded = el_bytes_data(log, &size);
  el_error error;
  el_error_init(&error);

  CHECK(size + 64 < sizeof text);
  memcpy(text, recorded, size);
  /* A closed ring: the line fails for its material, not for its WKT. */
  strcpy(text + size, "fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))\n");
  OK(el_replay_log(text, strlen(text), &replay, NULL));
  CHECK(el_replay_stopped(replay, &error) == EL_LOAD_ERROR && error.index == 4);
  CHECK(strncmp(error.message, "line 4", 6) == 0);
  CHECK(strstr(error.message, "material '300'") != NULL);
  CHECK(el_replay_edits(replay) == 2);
  OK(el_replay_landscape(replay, &replayed, NULL));
  CHECK(hash_of(replayed) == hash_of(world));
  report = report_of(replay);
  CHECK(contains(report, "\"stopped_at_line\":4"));
  el_bytes_destroy(report);
  el_landscape_destroy(replayed);
  el_replay_destroy(replay);

  OK(el_replay_log(no_world, strlen(no_world), &replay, NULL));
  replayed = NULL;
  CHECK(el_replay_landscape(replay, &replayed, &error) == EL_LOAD_ERROR && replayed == NULL);
  CHECK(error.index == 1 && el_replay_edits(replay) == 0);
  report = report_of(replay);
  CHECK(contains(report, "{\"edits\":0,\"stopped_at_line\":1,"));
  el_bytes_destroy(report);
  el_replay_destroy(replay);
  CHECK(el_replay_log(NULL, 5, &replay, NULL) == EL_NULL_ARGUMENT);
}

/* el_replay_*: a log recorded through the C API, replayed. */
static void test_replay_log(void) {
  const el_box box = {{0, 0}, {1024, 512}};
  const el_point center = {512, 256};
  el_landscape* world = NULL;
  el_shape* blast = NULL;
  el_shape* ore = square(100, 100, 50);
  el_bytes* log = NULL;

  OK(el_landscape_create(&box, 1, NULL, &world, NULL));
  OK(el_landscape_start_log(world, NULL));
  OK(el_shape_circle(&center, 100, &blast, NULL));
  OK(el_landscape_carve(world, blast, NULL, NULL));
  OK(el_landscape_fill(world, ore, 3, NULL, NULL));
  OK(el_landscape_log(world, &log, NULL));
  test_replay_of_a_recorded_log(world, log);
  test_replay_that_stops(world, log);
  el_bytes_destroy(log);
  el_shape_destroy(ore);
  el_shape_destroy(blast);
  el_landscape_destroy(world);
}

/* The game layer: chains and islands kept in step from change sets, detach, meshes, pieces. */
static void test_game_layer(void) {
  const el_box box = {{0, 0}, {1024, 512}};
  el_landscape* world = NULL;
  el_surface_tracker* surface = NULL;
  el_island_tracker* islands = NULL;
  el_shape* ground = square(0, 0, 100); /* on the border: anchored */
  el_shape* floating = square(400, 300, 40);
  el_changes* changes = NULL;
  el_chains* chains = NULL;
  el_islands* found = NULL;
  el_detached* detached = NULL;
  el_meshes* meshes = NULL;
  el_detached_info info;
  el_error error;
  size_t n = 0, points = 0;
  const el_chain_info* chain;
  const el_island_info* island;
  el_error_init(&error);

  OK(el_landscape_create(&box, 0, NULL, &world, NULL));
  OK(el_surface_tracker_create(world, NULL, &surface, NULL));
  OK(el_island_tracker_create(world, NULL, &islands, NULL));
  OK(el_landscape_fill(world, ground, 1, &changes, NULL));
  OK(el_surface_tracker_update(surface, world, changes, &chains, NULL));
  chain = el_chains_info(chains, &n);
  el_chains_points(chains, &points);
  CHECK(n >= 1 && points >= 2 && chain[0].id >= 1 && chain[0].closed == 0);
  CHECK(el_chains_materials(chains, NULL)[0] == 1);
  el_chains_destroy(chains);
  OK(el_island_tracker_update(islands, world, changes, &found, NULL));
  CHECK(el_islands_count(found) == 0); /* the ground touches the border */
  el_islands_destroy(found);
  el_changes_destroy(changes);

  OK(el_landscape_fill(world, floating, 2, &changes, NULL));
  OK(el_surface_tracker_update(surface, world, changes, &chains, NULL));
  el_chains_info(chains, &n);
  CHECK(n == 1 && el_chains_info(chains, NULL)[0].closed == 1);
  el_chains_destroy(chains);
  OK(el_island_tracker_update(islands, world, changes, &found, NULL));
  island = el_islands_info(found, &n);
  CHECK(n == 1 && island[0].twice_area.lo == 2 * 40 * 40 && island[0].piece_count >= 1);
  CHECK(el_polygons_materials(el_islands_pieces(found), NULL)[island[0].first_piece] == 2);
  OK(el_mesh_update(changes, &meshes, NULL));
  {
    size_t triangles = 0, offsets = 0;
    el_meshes_triangles(meshes, &triangles);
    el_meshes_triangle_offsets(meshes, &offsets);
    CHECK(triangles == 3 * 2 && offsets == 2 && el_polygons_count(el_meshes_polygons(meshes)) == 1);
  }
  el_meshes_destroy(meshes);
  el_changes_destroy(changes);

  CHECK(el_detach(world, found, 1, &detached, &error) == EL_INDEX_OUT_OF_RANGE);
  OK(el_detach(world, found, 0, &detached, NULL));
  OK(el_detached_summary(detached, &info, NULL));
  CHECK(info.twice_area.lo == 3200 && info.centroid_x_num.lo == 420 * info.centroid_den.lo);
  CHECK(el_polygons_count(el_detached_regions(detached)) == 1);
  {
    const uint8_t at = 0;
    uint8_t m = 9;
    const el_point inside = {420, 320};
    OK(el_landscape_material_at(world, &inside, &m, NULL));
    CHECK(m == at);
  }
  OK(el_surface_tracker_update(surface, world, el_detached_changes(detached), &chains, NULL));
  el_chains_removed(chains, &n);
  CHECK(n == 1);
  el_chains_destroy(chains);
  el_changes_destroy((el_changes*)el_detached_changes(detached)); /* borrowed: a no-op */
  CHECK(el_detach(world, found, 0, &detached, &error) == EL_STALE_ISLAND);
  CHECK(error.index >= 1);
  el_detached_destroy(detached);
  el_islands_destroy(found);

  { /* an L as convex pieces */
    const el_point l[6] = {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
    const el_point bow[4] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    el_polygons* pieces = NULL;
    OK(el_convex_pieces(l, 6, 8, &pieces, NULL));
    CHECK(el_polygons_count(pieces) == 2);
    el_polygons_destroy(pieces);
    CHECK(el_convex_pieces(l, 6, 2, &pieces, &error) == EL_INVALID_ARGUMENT && error.minimum == 3);
    CHECK(el_convex_pieces(bow, 4, 8, &pieces, &error) == EL_INVALID_INPUT);
  }
  el_surface_tracker_destroy(surface);
  el_island_tracker_destroy(islands);
  el_shape_destroy(ground);
  el_shape_destroy(floating);
  el_landscape_destroy(world);
}

static void test_null_is_harmless(void) {
  size_t count = 5;
  el_landscape_destroy(NULL);
  el_shape_destroy(NULL);
  el_changes_destroy(NULL);
  el_polygons_destroy(NULL);
  el_crossings_destroy(NULL);
  el_bytes_destroy(NULL);
  el_surface_tracker_destroy(NULL);
  el_island_tracker_destroy(NULL);
  el_chains_destroy(NULL);
  el_islands_destroy(NULL);
  el_detached_destroy(NULL);
  el_meshes_destroy(NULL);
  el_replay_destroy(NULL);
  el_error_init(NULL);
  CHECK(el_changes_removed(NULL, &count) == NULL && count == 0);
  CHECK(el_polygons_count(NULL) == 0 && el_replay_edits(NULL) == 0);
  CHECK(el_changes_copy_removed(NULL, NULL, 0, NULL) == EL_NULL_ARGUMENT);
}

int main(void) {
  test_version();
  test_edit_and_changes();
  test_errors_keep_the_world();
  test_queries();
  test_polygons_and_copy_to();
  test_snapshots_and_saves();
  test_relabel_and_log();
  test_shape_builders();
  test_shape_import();
  test_cells();
  test_replay_log();
  test_game_layer();
  test_game_driver();
  test_null_is_harmless();
  printf("capi: %d checks passed\n", checks);
  return 0;
}
