/* The mirror script (tests/mirror/README.md) through the C API, compared frame by frame with
 * the C++ run's hashes (the file given). The mirror: ids and their polygons' material and points
 * in a table kept sorted by id, from change sets only. Prints "mirror_c: 5000 frames". */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edgeland/edgeland.h"

#define FRAMES 5000

static void fail(int frame, const char* what) {
  fprintf(stderr, "mirror_c: frame %d: %s\n", frame, what);
  exit(1);
}

static void ok(el_status status, int frame, const char* what) {
  if (status != EL_OK) {
    fprintf(stderr, "mirror_c: frame %d: %s: %s\n", frame, what, el_status_name(status));
    exit(1);
  }
}

/* ---- random numbers ---- */
static uint64_t state = 36;
static uint64_t next(void) {
  uint64_t z;
  state += 0x9E3779B97F4A7C15ULL;
  z = state;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
static int64_t below(int64_t n) { return (int64_t)(next() % (uint64_t)n); }

/* ---- the mirror: entries sorted by id ---- */
typedef struct entry {
  uint64_t id;
  uint8_t material;
  uint32_t count;
  el_point* points;
} entry;
typedef struct mirror {
  entry* entries;
  size_t size, capacity;
} mirror;

static size_t find(const mirror* m, uint64_t id) { /* first index with entries[i].id >= id */
  size_t lo = 0, hi = m->size;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (m->entries[mid].id < id) lo = mid + 1; else hi = mid;
  }
  return lo;
}

static void erase(mirror* m, uint64_t id) {
  const size_t i = find(m, id);
  if (i == m->size || m->entries[i].id != id) return;
  free(m->entries[i].points);
  memmove(&m->entries[i], &m->entries[i + 1], (m->size - i - 1) * sizeof(entry));
  --m->size;
}

static void insert(mirror* m, uint64_t id, uint8_t material, const el_point* points, uint32_t n) {
  size_t i = find(m, id);
  entry e;
  e.id = id;
  e.material = material;
  e.count = n;
  e.points = malloc(n * sizeof(el_point));
  memcpy(e.points, points, n * sizeof(el_point));
  if (i < m->size && m->entries[i].id == id) {
    free(m->entries[i].points);
    m->entries[i] = e;
    return;
  }
  if (m->size == m->capacity) {
    m->capacity = m->capacity ? 2 * m->capacity : 256;
    m->entries = realloc(m->entries, m->capacity * sizeof(entry));
  }
  memmove(&m->entries[i + 1], &m->entries[i], (m->size - i) * sizeof(entry));
  m->entries[i] = e;
  ++m->size;
}

static void clear(mirror* m) {
  size_t i;
  for (i = 0; i < m->size; ++i) free(m->entries[i].points);
  m->size = 0;
}

static void copy_mirror(mirror* to, const mirror* from) {
  size_t i;
  clear(to);
  for (i = 0; i < from->size; ++i) {
    const entry* e = &from->entries[i];
    insert(to, e->id, e->material, e->points, e->count);
  }
}

static void add_polygons(mirror* m, const el_polygons* p) {
  const size_t n = el_polygons_count(p);
  const uint64_t* ids = el_polygons_ids(p, NULL);
  const uint8_t* materials = el_polygons_materials(p, NULL);
  const uint32_t* offsets = el_polygons_offsets(p, NULL);
  const el_point* points = el_polygons_points(p, NULL);
  size_t i;
  for (i = 0; i < n; ++i) {
    insert(m, ids[i], materials[i], points + offsets[i], offsets[i + 1] - offsets[i]);
  }
}

static void apply(mirror* m, el_changes* changes) {
  size_t n = 0, i;
  const uint64_t* removed = el_changes_removed(changes, &n);
  for (i = 0; i < n; ++i) erase(m, removed[i]);
  add_polygons(m, el_changes_added(changes));
  el_changes_destroy(changes);
}

static int same(const mirror* a, const mirror* b) {
  size_t i;
  if (a->size != b->size) return 0;
  for (i = 0; i < a->size; ++i) {
    const entry *x = &a->entries[i], *y = &b->entries[i];
    if (x->id != y->id || x->material != y->material || x->count != y->count) return 0;
    if (memcmp(x->points, y->points, x->count * sizeof(el_point)) != 0) return 0;
  }
  return 1;
}

static void world_polygons(const el_landscape* world, mirror* out) {
  el_box box;
  el_polygons* p = NULL;
  ok(el_landscape_world(world, &box, NULL), -1, "world");
  ok(el_landscape_polygons_in(world, &box, &p, NULL), -1, "polygons_in");
  clear(out);
  add_polygons(out, p);
  el_polygons_destroy(p);
}

static uint64_t hash_of(const el_landscape* world) {
  uint64_t h = 0;
  ok(el_landscape_state_hash(world, &h, NULL), -1, "state_hash");
  return h;
}

/* ---- the script ---- */
static el_shape* draw_shape(void) {
  const int64_t kind = below(3);
  el_point c;
  int64_t r;
  el_shape* s = NULL;
  c.x = below(2176) - 64;
  c.y = below(1152) - 64;
  r = 4 + below(60);
  if (kind == 0) {
    ok(el_shape_circle(&c, r, &s, NULL), -1, "circle");
  } else if (kind == 1) {
    const int64_t h = 1 + r / 2;
    el_box b;
    b.min.x = c.x - r;
    b.min.y = c.y - h;
    b.max.x = c.x + r;
    b.max.y = c.y + h;
    ok(el_shape_box(&b, &s, NULL), -1, "box");
  } else {
    const int64_t sides = 3 + below(6);
    const int64_t phase = below(16);
    ok(el_shape_regular_polygon(&c, r, sides, phase, 16, &s, NULL), -1, "regular polygon");
  }
  return s;
}

static el_changes* draw_edit(el_landscape* world, int frame) {
  const int64_t op = below(5);
  el_shape* shape = draw_shape();
  el_changes* changes = NULL;
  if (op == 0) {
    ok(el_landscape_carve(world, shape, &changes, NULL), frame, "carve");
  } else if (op == 1) {
    ok(el_landscape_fill(world, shape, (int32_t)(1 + below(4)), &changes, NULL), frame, "fill");
  } else if (op == 2) {
    ok(el_landscape_fill_empty(world, shape, (int32_t)(1 + below(4)), &changes, NULL), frame,
       "fill_empty");
  } else if (op == 3) {
    const int32_t from = (int32_t)below(5);
    const int32_t to = (int32_t)below(5);
    ok(el_landscape_replace(world, shape, from, to, &changes, NULL), frame, "replace");
  } else {
    int32_t pairs[4];
    int i;
    for (i = 0; i < 4; ++i) pairs[i] = (int32_t)below(5);
    ok(el_landscape_relabel(world, shape, pairs, 2, &changes, NULL), frame, "relabel");
  }
  el_shape_destroy(shape);
  return changes;
}

static void bad_input(el_landscape* world, int frame) {
  const uint64_t before = hash_of(world);
  const int64_t bowtie[8] = {0, 0, 10, 10, 10, 0, 0, 10};
  const int64_t square[8] = {0, 0, 10, 0, 10, 10, 0, 10};
  const uint32_t offsets[2] = {0, 4};
  el_shape* s = NULL;
  el_error e;
  el_error_init(&e);
  if (el_shape_create(bowtie, offsets, 1, &s, &e) != EL_INVALID_INPUT ||
      e.kind != EL_RULE_SELF_INTERSECTION) {
    fail(frame, "the bow tie");
  }
  ok(el_shape_create(square, offsets, 1, &s, NULL), frame, "square");
  if (el_landscape_fill(world, s, 300, NULL, &e) != EL_INVALID_MATERIAL || e.value != 300) {
    fail(frame, "material 300");
  }
  el_shape_destroy(s);
  if (hash_of(world) != before) fail(frame, "a refused edit changed the world");
}

int main(int argc, char** argv) {
  FILE* expected;
  el_landscape* world = NULL;
  el_landscape* snapshot = NULL;
  mirror m = {NULL, 0, 0}, m_snapshot = {NULL, 0, 0}, actual = {NULL, 0, 0};
  const el_box box = {{0, 0}, {2048, 1024}};
  int f;
  if (argc != 2 || (expected = fopen(argv[1], "r")) == NULL) {
    fprintf(stderr, "usage: mirror_c HASHES (the C++ run's)\n");
    return 2;
  }
  ok(el_landscape_create(&box, 1, NULL, &world, NULL), -1, "create");
  world_polygons(world, &m);
  for (f = 0; f < FRAMES; ++f) {
    int64_t edits, e;
    int frame_read = -1;
    uint64_t hash_read = 0;
    if (f % 1000 == 500) bad_input(world, f);
    edits = 1 + below(3);
    for (e = 0; e < edits; ++e) apply(&m, draw_edit(world, f));
    if (f % 100 == 90) {
      el_landscape_destroy(snapshot);
      ok(el_landscape_clone(world, &snapshot, NULL), f, "clone");
      copy_mirror(&m_snapshot, &m);
    }
    if (f % 100 == 99) {
      el_landscape_destroy(world);
      ok(el_landscape_clone(snapshot, &world, NULL), f, "undo");
      copy_mirror(&m, &m_snapshot);
    }
    if (f % 500 == 499) {
      el_bytes* bytes = NULL;
      size_t size = 0;
      const uint8_t* data;
      ok(el_landscape_save(world, &bytes, NULL), f, "save");
      data = el_bytes_data(bytes, &size);
      el_landscape_destroy(world);
      world = NULL;
      ok(el_landscape_load(data, size, NULL, &world, NULL), f, "load");
      el_bytes_destroy(bytes);
    }
    if (fscanf(expected, "%d %" SCNu64, &frame_read, &hash_read) != 2 || frame_read != f) {
      fail(f, "the C++ run's hash file ends early");
    }
    if (hash_of(world) != hash_read) fail(f, "state hash differs from the C++ run's");
    if (f % 100 == 99 || f == FRAMES - 1) {
      world_polygons(world, &actual);
      if (!same(&m, &actual)) fail(f, "mirror differs from the world");
    }
  }
  fclose(expected);
  clear(&m);
  clear(&m_snapshot);
  clear(&actual);
  free(m.entries);
  free(m_snapshot.entries);
  free(actual.entries);
  el_landscape_destroy(snapshot);
  el_landscape_destroy(world);
  printf("mirror_c: %d frames\n", FRAMES);
  return 0;
}
