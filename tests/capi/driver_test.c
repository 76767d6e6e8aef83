/* The game driver from C99 (edgeland.h, "the game driver"): a frame's edits as one batch and the
 * update it returns (the change set, chains with their ghosts, meshes, debris with its regions,
 * convex pieces and meshes), a mirror of the chains kept from updates alone, buried bodies, a
 * reset to a snapshot, and typed errors that leave the driver as it was. Linked into the C test
 * (capi_test.c calls test_game_driver). */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "edgeland/edgeland.h"

enum { kMaxChains = 512 };

/* The chains a game holds, kept from updates alone (their ids and infos). */
typedef struct chain_mirror {
  size_t count;
  el_chain_info info[kMaxChains];
} chain_mirror;

static void mirror_remove(chain_mirror* m, uint64_t id) {
  size_t i;
  for (i = 0; i < m->count; ++i) {
    if (m->info[i].id == id) {
      m->info[i] = m->info[--m->count];
      return;
    }
  }
  CHECK(0 && "an update removed a chain the game does not hold");
}

static void mirror_apply(chain_mirror* m, const el_chains* update) {
  size_t removed = 0, added = 0, i;
  const uint64_t* gone = el_chains_removed(update, &removed);
  const el_chain_info* info = el_chains_info(update, &added);
  for (i = 0; i < removed; ++i) mirror_remove(m, gone[i]);
  for (i = 0; i < added; ++i) {
    CHECK(m->count < kMaxChains);
    m->info[m->count++] = info[i];
  }
}

/* The mirror holds exactly the driver's chains (same ids, cells and ghosts). */
static void check_mirror(const chain_mirror* m, const el_game_driver* driver) {
  el_chains* all = NULL;
  size_t n = 0, i, k;
  const el_chain_info* info;
  OK(el_game_driver_chains(driver, &all, NULL));
  info = el_chains_info(all, &n);
  CHECK(n == m->count);
  for (i = 0; i < n; ++i) {
    int found = 0;
    for (k = 0; k < m->count; ++k) {
      if (m->info[k].id == info[i].id) found = memcmp(&m->info[k], &info[i], sizeof(*info)) == 0;
    }
    CHECK(found);
  }
  el_chains_destroy(all);
}

static int same_point(el_point a, el_point b) { return a.x == b.x && a.y == b.y; }

/* Where one open chain ends and the next begins (a cell line), each one's ghost is the other's
 * point beside the joint: the surface goes on smoothly. Returns the joints seen. */
static size_t check_ghosts(const el_game_driver* driver) {
  el_chains* all = NULL;
  size_t n = 0, i, k, joints = 0;
  const el_chain_info* info;
  const uint32_t* offsets;
  const el_point* p;
  OK(el_game_driver_chains(driver, &all, NULL));
  info = el_chains_info(all, &n);
  offsets = el_chains_offsets(all, NULL);
  p = el_chains_points(all, NULL);
  for (i = 0; i < n; ++i) {
    const el_point last = p[offsets[i + 1] - 1], before_last = p[offsets[i + 1] - 2];
    if (info[i].closed) continue;
    for (k = 0; k < n; ++k) {
      if (k == i || info[k].closed || !same_point(p[offsets[k]], last)) continue;
      CHECK(same_point(info[i].ghost_next, p[offsets[k] + 1]));
      CHECK(same_point(info[k].ghost_prev, before_last));
      ++joints;
    }
  }
  el_chains_destroy(all);
  return joints;
}

static el_shape* box_shape(int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
  const el_box b = {{x0, y0}, {x1, y1}};
  el_shape* shape = NULL;
  OK(el_shape_box(&b, &shape, NULL));
  return shape;
}

/* An empty world of 8 x 8 cells (so the ground's surface crosses cell lines). */
static el_landscape* cell_world(uint64_t max_shape_vertices) {
  const el_box box = {{0, 0}, {1024, 512}};
  el_landscape_config config;
  el_landscape* world = NULL;
  el_landscape_config_init(&config);
  config.grid_depth = 3;
  config.flags = EL_LANDSCAPE_CHECKED;
  config.max_shape_vertices = max_shape_vertices;
  OK(el_landscape_create(&box, 0, &config, &world, NULL));
  return world;
}

static uint64_t driver_hash(const el_game_driver* driver) {
  el_landscape* now = NULL;
  uint64_t h = 0;
  OK(el_game_driver_landscape(driver, &now, NULL));
  OK(el_landscape_state_hash(now, &h, NULL));
  el_landscape_destroy(now);
  return h;
}

/* Frame 1: ground on the border (held) and a rock in the air (debris, detached at once). */
static void first_frame(el_game_driver* driver, chain_mirror* mirror) {
  el_edits* edits = NULL;
  el_shape* ground = box_shape(0, 0, 1024, 100);
  el_shape* rock = box_shape(400, 300, 440, 340);
  el_game_update* update = NULL;
  el_game_work work;
  const el_debris_info* debris;
  const el_meshes* meshes;
  size_t n = 0, triangles = 0;
  el_landscape* now = NULL;
  const el_point inside = {420, 320};
  uint8_t m = 9;

  OK(el_edits_create(&edits, NULL));
  OK(el_edits_fill(edits, ground, 1, NULL));
  OK(el_edits_fill(edits, rock, 2, NULL));
  CHECK(el_edits_count(edits) == 2);
  OK(el_game_driver_apply(driver, edits, &update, NULL));
  mirror_apply(mirror, el_game_update_chains(update));
  CHECK(mirror->count >= 2);

  debris = el_game_update_debris(update, &n);
  CHECK(n == 1 && debris[0].twice_area.lo == 2 * 40 * 40 && debris[0].twice_area.hi == 0);
  CHECK(debris[0].centroid_x_num.lo == 420 * debris[0].centroid_den.lo);
  CHECK(debris[0].centroid_y_num.lo == 320 * debris[0].centroid_den.lo);
  CHECK(debris[0].bounds.min.x == 400 && debris[0].bounds.max.y == 340);
  CHECK(debris[0].region_count == 1 && debris[0].piece_count == 1);
  CHECK(el_polygons_materials(el_game_update_debris_pieces(update), NULL)[0] == 2);
  el_polygons_points(el_game_update_debris_pieces(update), &n);
  CHECK(n == 4);
  CHECK(el_polygons_count(el_game_update_debris_regions(update)) == 1);
  meshes = el_game_update_debris_meshes(update);
  el_meshes_triangles(meshes, &triangles);
  CHECK(el_polygons_count(el_meshes_polygons(meshes)) == 1 && triangles == 3 * 2);

  /* The meshes of the ground's new polygons; the rock went as debris. */
  meshes = el_game_update_meshes(update);
  CHECK(el_polygons_count(el_meshes_polygons(meshes)) >= 1);
  CHECK(el_polygons_count(el_changes_added(el_game_update_changes(update))) ==
        el_polygons_count(el_meshes_polygons(meshes)));
  el_game_work_init(&work);
  OK(el_game_update_work(update, &work, NULL));
  CHECK(work.cells_scanned >= 1 && work.islands_detached == 1 && work.debris_waiting == 0);
  OK(el_game_driver_landscape(driver, &now, NULL));
  OK(el_landscape_material_at(now, &inside, &m, NULL));
  CHECK(m == 0);
  el_game_update_destroy(update);
  el_landscape_destroy(now);
  el_edits_destroy(edits);
  el_shape_destroy(ground);
  el_shape_destroy(rock);
}

/* A fill through a body's box buries it; one elsewhere does not. */
static void buried_bodies(el_game_driver* driver, chain_mirror* mirror) {
  el_edits* edits = NULL;
  el_shape* pillar = box_shape(600, 60, 650, 250);
  el_game_update* update = NULL;
  const el_box inside = {{610, 210}, {620, 220}}, far = {{100, 400}, {110, 410}};
  int32_t buried = -1;

  OK(el_edits_create(&edits, NULL));
  OK(el_edits_fill(edits, pillar, 3, NULL));
  OK(el_game_driver_apply(driver, edits, &update, NULL));
  mirror_apply(mirror, el_game_update_chains(update));
  OK(el_game_driver_buried(driver, &inside, &buried, NULL));
  CHECK(buried == 1);
  OK(el_game_driver_buried(driver, &far, &buried, NULL));
  CHECK(buried == 0);
  el_game_update_destroy(update);
  el_edits_destroy(edits);
  el_shape_destroy(pillar);
}

/* An undo: a carve, then the driver reset to the snapshot from before it. */
static void reset_to_snapshot(el_game_driver* driver, chain_mirror* mirror) {
  el_landscape* before = NULL;
  el_edits* edits = NULL;
  el_shape* crater = NULL;
  el_game_update* update = NULL;
  const el_point center = {300, 100};
  uint64_t hash_before = 0;

  OK(el_game_driver_landscape(driver, &before, NULL));
  OK(el_landscape_state_hash(before, &hash_before, NULL));
  OK(el_shape_circle(&center, 60, &crater, NULL));
  OK(el_edits_create(&edits, NULL));
  OK(el_edits_carve(edits, crater, NULL));
  OK(el_game_driver_apply(driver, edits, &update, NULL));
  mirror_apply(mirror, el_game_update_chains(update));
  el_game_update_destroy(update);
  CHECK(driver_hash(driver) != hash_before);
  check_mirror(mirror, driver);

  OK(el_game_driver_reset(driver, before, &update, NULL));
  mirror_apply(mirror, el_game_update_chains(update));
  CHECK(driver_hash(driver) == hash_before);
  check_mirror(mirror, driver);
  el_game_update_destroy(update);
  el_edits_destroy(edits);
  el_shape_destroy(crater);
  el_landscape_destroy(before);
}

/* Typed errors: a bad material when added (the batch unchanged), a shape past the world's limit
 * when applied (the driver unchanged, *update untouched), options an update could not honour. */
static void errors_change_nothing(void) {
  el_landscape* world = cell_world(16);
  el_game_driver* driver = NULL;
  el_game_options options;
  el_edits* edits = NULL;
  el_shape* small = box_shape(10, 10, 50, 50);
  el_shape* round = NULL;
  el_game_update* update = NULL;
  el_error error;
  const el_point center = {500, 300};
  uint64_t hash = 0;
  chain_mirror mirror;

  el_error_init(&error);
  el_game_options_init(&options);
  options.max_piece_vertices = 2;
  CHECK(el_game_driver_create(world, &options, &driver, &error) == EL_INVALID_ARGUMENT);
  CHECK(driver == NULL && error.value == 2 && error.minimum == 3);
  options.struct_size = 0;
  CHECK(el_game_driver_create(world, &options, &driver, &error) == EL_VERSION_MISMATCH);
  OK(el_game_driver_create(world, NULL, &driver, NULL));

  OK(el_edits_create(&edits, NULL));
  OK(el_edits_carve(edits, small, NULL));
  CHECK(el_edits_fill(edits, small, 300, &error) == EL_INVALID_MATERIAL && error.value == 300);
  CHECK(el_edits_replace(edits, small, 1, -1, &error) == EL_INVALID_MATERIAL);
  CHECK(el_edits_count(edits) == 1);
  OK(el_shape_circle(&center, 100, &round, NULL));
  OK(el_edits_fill(edits, round, 1, NULL));
  OK(el_game_driver_apply(driver, NULL, NULL, NULL)); /* no edits: only the debris queue moves */
  mirror.count = 0;
  {
    el_chains* all = NULL;
    OK(el_game_driver_chains(driver, &all, NULL));
    mirror_apply(&mirror, all);
    el_chains_destroy(all);
  }
  hash = driver_hash(driver);
  CHECK(el_game_driver_apply(driver, edits, &update, &error) == EL_LIMIT_EXCEEDED);
  CHECK(update == NULL && error.kind == EL_LIMIT_SHAPE_VERTICES && error.limit == 16);
  CHECK(driver_hash(driver) == hash);
  check_mirror(&mirror, driver);

  CHECK(el_game_driver_apply(NULL, edits, &update, &error) == EL_NULL_ARGUMENT);
  CHECK(el_edits_carve(edits, NULL, &error) == EL_NULL_ARGUMENT);
  CHECK(el_game_driver_buried(driver, NULL, NULL, &error) == EL_NULL_ARGUMENT);
  el_edits_clear(edits);
  CHECK(el_edits_count(edits) == 0);
  el_game_driver_destroy(driver);
  el_edits_destroy(edits);
  el_shape_destroy(small);
  el_shape_destroy(round);
  el_landscape_destroy(world);
}

/* Pieces of at most 3 vertices: a square rock falls as two triangles. */
static void triangle_pieces(void) {
  el_landscape* world = cell_world(1u << 20);
  el_game_driver* driver = NULL;
  el_game_options options;
  el_edits* edits = NULL;
  el_shape* rock = box_shape(400, 300, 440, 340);
  el_game_update* update = NULL;
  const el_debris_info* debris;
  size_t n = 0;

  el_game_options_init(&options);
  CHECK(options.max_piece_vertices == 8 && options.flags == (EL_GAME_MESHES | EL_GAME_DEBRIS));
  options.max_piece_vertices = 3;
  options.flags = EL_GAME_DEBRIS; /* no meshes */
  OK(el_game_driver_create(world, &options, &driver, NULL));
  OK(el_edits_create(&edits, NULL));
  OK(el_edits_fill(edits, rock, 4, NULL));
  OK(el_game_driver_apply(driver, edits, &update, NULL));
  debris = el_game_update_debris(update, &n);
  CHECK(n == 1 && debris[0].piece_count == 2);
  CHECK(el_polygons_count(el_meshes_polygons(el_game_update_meshes(update))) == 0);
  CHECK(el_polygons_count(el_meshes_polygons(el_game_update_debris_meshes(update))) == 0);
  {
    el_debris_info copy[1];
    CHECK(el_game_update_copy_debris(update, NULL, 0, &n) == EL_BUFFER_TOO_SMALL && n == 1);
    OK(el_game_update_copy_debris(update, copy, 1, &n));
    CHECK(memcmp(copy, debris, sizeof copy) == 0);
  }
  el_game_update_destroy(update);
  el_edits_destroy(edits);
  el_shape_destroy(rock);
  el_game_driver_destroy(driver);
  el_landscape_destroy(world);
}

void test_game_driver(void) {
  el_landscape* world = cell_world(1u << 20);
  el_game_driver* driver = NULL;
  chain_mirror mirror;
  uint64_t world_hash = 0;

  mirror.count = 0;
  OK(el_landscape_state_hash(world, &world_hash, NULL));
  OK(el_game_driver_create(world, NULL, &driver, NULL));
  first_frame(driver, &mirror);
  check_mirror(&mirror, driver);
  CHECK(check_ghosts(driver) == 7); /* the ground's top crosses 7 cell lines */
  buried_bodies(driver, &mirror);
  check_mirror(&mirror, driver);
  reset_to_snapshot(driver, &mirror);
  CHECK(el_game_driver_debris_waiting(driver) == 0);
  {
    uint64_t h = 0; /* the caller's landscape is its own: the driver took a snapshot */
    OK(el_landscape_state_hash(world, &h, NULL));
    CHECK(h == world_hash);
  }
  el_game_driver_destroy(driver);
  el_landscape_destroy(world);
  errors_change_nothing();
  triangle_pieces();

  el_game_driver_destroy(NULL);
  el_game_update_destroy(NULL);
  el_edits_destroy(NULL);
  el_edits_clear(NULL);
  CHECK(el_edits_count(NULL) == 0 && el_game_driver_debris_waiting(NULL) == 0);
  CHECK(el_game_update_chains(NULL) == NULL && el_game_update_changes(NULL) == NULL);
  CHECK(el_game_update_debris(NULL, NULL) == NULL);
}
