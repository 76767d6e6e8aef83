// EL_OUT_OF_MEMORY, produced systematically (issue 36): each C API call below runs again and
// again with allocation 0, 1, 2, ... of the call failing (failing_allocator.hpp), once with only
// that allocation failing and once with every allocation from it on failing, until a run in
// which no allocation failed. Every run must keep the error contract of edgeland.h:
// - the status is EL_OK or EL_OUT_OF_MEMORY, nothing else, and no crash or abort (one documented
//   exception: el_landscape_load, AlsoAccepted below);
// - on EL_OUT_OF_MEMORY, el_error says so, with std::bad_alloc's message;
// - on failure the out-parameters are left as they were (NULL here);
// - a failed call changes nothing: the landscapes it was given hash as before (a failed carve's
//   also passes check()), and the same call then succeeds on the same objects, with the result
//   of a run that never met a fault (a failed driver apply: on a new driver, and on the driver
//   reset as edgeland.h asks, whose update takes the game's chains to the driver's);
// - a call that succeeded although an allocation failed (the library absorbed it) gave that
//   same result too.
// Everything is freed on every path: under the sanitizer build, LeakSanitizer checks the failure
// paths for leaks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "edgeland/edgeland.h"
#include "failing_allocator.hpp"

namespace {

using edgeland::test::FaultMode;

// Far more allocations than any call here makes: a loop that reaches it never ends.
constexpr std::size_t kMaxRuns = 100000;

template <class T, void (*Destroy)(T*)>
struct Destroyer {
  void operator()(T* p) const { Destroy(p); }
};
using LandscapePtr = std::unique_ptr<el_landscape, Destroyer<el_landscape, el_landscape_destroy>>;
using ShapePtr = std::unique_ptr<el_shape, Destroyer<el_shape, el_shape_destroy>>;
using ChangesPtr = std::unique_ptr<el_changes, Destroyer<el_changes, el_changes_destroy>>;
using BytesPtr = std::unique_ptr<el_bytes, Destroyer<el_bytes, el_bytes_destroy>>;
using EditsPtr = std::unique_ptr<el_edits, Destroyer<el_edits, el_edits_destroy>>;
using DriverPtr =
    std::unique_ptr<el_game_driver, Destroyer<el_game_driver, el_game_driver_destroy>>;
using UpdatePtr =
    std::unique_ptr<el_game_update, Destroyer<el_game_update, el_game_update_destroy>>;
using ReplayPtr = std::unique_ptr<el_replay, Destroyer<el_replay, el_replay_destroy>>;
using PolygonsPtr = std::unique_ptr<el_polygons, Destroyer<el_polygons, el_polygons_destroy>>;

// ---- one run ---------------------------------------------------------------------------------

struct Outcome {
  el_status status = EL_OK;
  bool fired = false;  // an allocation failed during the call
  el_error error{};
};

// call(error) with this thread's allocation `skip` of the call failing (and, persistent, every
// later one): only the call runs while the fault is armed.
template <class Call>
Outcome with_fault(std::size_t skip, FaultMode mode, Call&& call) {
  Outcome o;
  el_error_init(&o.error);
  edgeland::test::arm_allocation_fault(skip, mode);
  o.status = call(&o.error);
  o.fired = edgeland::test::disarm_allocation_fault();
  return o;
}

bool failed(const Outcome& o) { return o.status != EL_OK; }

// How a call may report memory running out, besides EL_OUT_OF_MEMORY.
enum class AlsoAccepted {
  kNothing,
  // el_landscape_load: the C++ loader turns std::bad_alloc into a LoadError (spatial/README.md,
  // "Save/load": "memory running out is a LoadError"), which the border translates as it
  // translates every LoadError. Accepted only with the loader's "out of memory" messages.
  kLoadErrorOutOfMemory,
};

bool load_error_out_of_memory(const Outcome& o) {
  const std::string message = o.error.message;
  return o.status == EL_LOAD_ERROR && o.error.status == EL_LOAD_ERROR &&
         message.starts_with("cannot load landscape at byte ") &&
         message.find(": out of memory") != std::string::npos;
}

// The status and el_error of one run: EL_OK without a fault; with one, EL_OK or EL_OUT_OF_MEMORY
// and its message (or what `also` accepts).
void expect_status(const Outcome& o, AlsoAccepted also) {
  const std::string said = std::string(el_status_name(o.status)) + ": " + o.error.message;
  if (!o.fired) {
    EXPECT_EQ(o.status, EL_OK) << said;
    return;
  }
  if (o.status == EL_OK) return;
  if (also == AlsoAccepted::kLoadErrorOutOfMemory && load_error_out_of_memory(o)) return;
  EXPECT_EQ(o.status, EL_OUT_OF_MEMORY) << said;
  EXPECT_EQ(o.error.status, EL_OUT_OF_MEMORY);
  EXPECT_STREQ(o.error.message, std::bad_alloc().what());
}

const char* mode_name(FaultMode mode) {
  return mode == FaultMode::kOnce ? "one allocation fails" : "every allocation from it fails";
}

// run(skip, mode) for skip = 0, 1, ... until a run in which no allocation failed, in both modes;
// run checks what the call left, and this the status. The first run must fail (every call here
// allocates), so the loop cannot pass by never reaching the fault.
template <class Run>
void for_each_fault(const char* call, Run&& run, AlsoAccepted also = AlsoAccepted::kNothing) {
  for (const FaultMode mode : {FaultMode::kOnce, FaultMode::kPersistent}) {
    std::size_t runs = 0, out_of_memory = 0, other = 0;
    for (bool fired = true; fired; ++runs) {
      ASSERT_LT(runs, kMaxRuns) << call << " never ran without a fault";
      SCOPED_TRACE(std::string(call) + ", " + mode_name(mode) + ": allocation " +
                   std::to_string(runs));
      const Outcome o = run(runs, mode);
      expect_status(o, also);
      if (::testing::Test::HasFailure()) return;
      out_of_memory += o.status == EL_OUT_OF_MEMORY ? 1 : 0;
      other += failed(o) && o.status != EL_OUT_OF_MEMORY ? 1 : 0;
      fired = o.fired;
    }
    EXPECT_GT(out_of_memory + other, 0u) << call << " never failed";
    std::printf("%s, %s: %zu runs, %zu EL_OUT_OF_MEMORY", call, mode_name(mode), runs,
                out_of_memory);
    if (other > 0) std::printf(", %zu EL_LOAD_ERROR (out of memory)", other);
    std::printf("\n");
  }
}

// A call that makes one handle, make(&out, error): on failure `out` stays NULL; on success
// value_of(out) is `expected`, the value of a run that met no fault.
template <class Ptr, class Make, class ValueOf, class Value>
void expect_made(const char* call, Make&& make, ValueOf&& value_of, const Value& expected,
                 AlsoAccepted also = AlsoAccepted::kNothing) {
  const auto run = [&](std::size_t skip, FaultMode mode) {
    typename Ptr::pointer out = nullptr;
    const Outcome o = with_fault(skip, mode, [&](el_error* e) { return make(&out, e); });
    const Ptr made(out);
    if (failed(o)) {
      EXPECT_EQ(out, nullptr);
    } else {
      EXPECT_TRUE(value_of(out) == expected);
    }
    return o;
  };
  for_each_fault(call, run, also);
}

// ---- values to compare, read with no fault armed ----------------------------------------------

std::uint64_t hash_of(const el_landscape* l) {
  std::uint64_t h = 0;
  EXPECT_EQ(el_landscape_state_hash(l, &h, nullptr), EL_OK);
  return h;
}

// The problems Landscape::check() finds (empty: valid).
std::string problems_of(const el_landscape* l) {
  el_bytes* raw = nullptr;
  EXPECT_EQ(el_landscape_check(l, &raw, nullptr), EL_OK);
  const BytesPtr problems(raw);
  std::size_t size = 0;
  const std::uint8_t* text = el_bytes_data(problems.get(), &size);
  return std::string(reinterpret_cast<const char*>(text), size);
}

std::string text_of(const el_bytes* bytes) {
  std::size_t size = 0;
  const std::uint8_t* data = el_bytes_data(bytes, &size);
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A shape's polygons: the offsets, then the points' coordinates.
std::vector<std::int64_t> polygons_of(const el_shape* shape) {
  el_polygons* raw = nullptr;
  EXPECT_EQ(el_shape_polygons(shape, &raw, nullptr), EL_OK);
  const PolygonsPtr polygons(raw);
  std::vector<std::int64_t> out;
  std::size_t n = 0;
  const std::uint32_t* offsets = el_polygons_offsets(polygons.get(), &n);
  out.insert(out.end(), offsets, offsets + n);
  const el_point* points = el_polygons_points(polygons.get(), &n);
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(points[i].x);
    out.push_back(points[i].y);
  }
  return out;
}

std::size_t removed_count(const el_changes* changes) {
  std::size_t n = 0;
  el_changes_removed(changes, &n);
  return n;
}

LandscapePtr clone_of(const el_landscape* l) {
  el_landscape* raw = nullptr;
  EXPECT_EQ(el_landscape_clone(l, &raw, nullptr), EL_OK);
  return LandscapePtr(raw);
}

ShapePtr circle_shape(std::int64_t x, std::int64_t y, std::int64_t radius) {
  const el_point center = {x, y};
  el_shape* raw = nullptr;
  EXPECT_EQ(el_shape_circle(&center, radius, &raw, nullptr), EL_OK);
  return ShapePtr(raw);
}

ShapePtr box_shape(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  const el_box box = {{x0, y0}, {x1, y1}};
  el_shape* raw = nullptr;
  EXPECT_EQ(el_shape_box(&box, &raw, nullptr), EL_OK);
  return ShapePtr(raw);
}

const el_box kWorld = {{0, 0}, {1024, 512}};

// A grid of 2^depth x 2^depth cells, so edits cross cell lines.
el_landscape_config cells_config(std::int32_t depth = 3) {
  el_landscape_config c;
  el_landscape_config_init(&c);
  c.grid_depth = depth;
  return c;
}

// Ground along the bottom with an ore vein and a crater: several materials and polygons in
// several cells, and nothing that falls.
LandscapePtr ground_world(std::int32_t depth = 3) {
  const el_landscape_config config = cells_config(depth);
  el_landscape* raw = nullptr;
  EXPECT_EQ(el_landscape_create(&kWorld, 0, &config, &raw, nullptr), EL_OK);
  LandscapePtr world(raw);
  EXPECT_EQ(el_landscape_fill(world.get(), box_shape(0, 0, 1024, 200).get(), 1, nullptr, nullptr),
            EL_OK);
  EXPECT_EQ(el_landscape_fill(world.get(), circle_shape(300, 150, 60).get(), 2, nullptr, nullptr),
            EL_OK);
  EXPECT_EQ(el_landscape_carve(world.get(), circle_shape(700, 200, 50).get(), nullptr, nullptr),
            EL_OK);
  return world;
}

// The ground world with a rock floating above it (an island a game driver would detach).
LandscapePtr small_world() {
  LandscapePtr world = ground_world();
  EXPECT_EQ(
      el_landscape_fill(world.get(), box_shape(500, 350, 560, 400).get(), 3, nullptr, nullptr),
      EL_OK);
  return world;
}

// ---- landscapes ---------------------------------------------------------------------------------

TEST(CapiOutOfMemory, LandscapeCreate) {
  const el_landscape_config config = cells_config();
  el_landscape* raw = nullptr;
  ASSERT_EQ(el_landscape_create(&kWorld, 1, &config, &raw, nullptr), EL_OK);
  const std::uint64_t expected = hash_of(LandscapePtr(raw).get());
  expect_made<LandscapePtr>(
      "el_landscape_create",
      [&](el_landscape** out, el_error* e) {
        return el_landscape_create(&kWorld, 1, &config, out, e);
      },
      hash_of, expected);
}

TEST(CapiOutOfMemory, ShapeCircle) {
  const std::vector<std::int64_t> expected = polygons_of(circle_shape(512, 180, 90).get());
  const el_point center = {512, 180};
  expect_made<ShapePtr>(
      "el_shape_circle",
      [&](el_shape** out, el_error* e) { return el_shape_circle(&center, 90, out, e); },
      polygons_of, expected);
}

// A carve with a circle, each run on a snapshot of the same world (so the shared tree must come
// through a failed copy-on-write untouched too); after a failure the same carve on the same
// landscape succeeds with the result of the carve that never failed.
TEST(CapiOutOfMemory, LandscapeCarve) {
  const LandscapePtr world = small_world();
  const ShapePtr blast = circle_shape(512, 180, 90);
  const std::uint64_t world_hash = hash_of(world.get());
  std::uint64_t expected = 0;
  std::size_t expected_removed = 0;
  {
    const LandscapePtr reference = clone_of(world.get());
    el_changes* raw = nullptr;
    ASSERT_EQ(el_landscape_carve(reference.get(), blast.get(), &raw, nullptr), EL_OK);
    expected_removed = removed_count(ChangesPtr(raw).get());
    expected = hash_of(reference.get());
    ASSERT_NE(expected, world_hash);
    ASSERT_GT(expected_removed, 1u);
  }
  for_each_fault("el_landscape_carve", [&](std::size_t skip, FaultMode mode) {
    const LandscapePtr work = clone_of(world.get());
    el_changes* out = nullptr;
    const Outcome o = with_fault(skip, mode, [&](el_error* e) {
      return el_landscape_carve(work.get(), blast.get(), &out, e);
    });
    ChangesPtr changes(out);
    if (failed(o)) {
      EXPECT_EQ(out, nullptr);
      EXPECT_EQ(hash_of(work.get()), world_hash);
      EXPECT_EQ(hash_of(world.get()), world_hash);
      EXPECT_EQ(problems_of(work.get()), "");
      EXPECT_EQ(el_landscape_carve(work.get(), blast.get(), &out, nullptr), EL_OK);
      changes.reset(out);
    }
    EXPECT_EQ(hash_of(work.get()), expected);
    EXPECT_EQ(removed_count(changes.get()), expected_removed);
    return o;
  });
}

TEST(CapiOutOfMemory, LandscapeSave) {
  const LandscapePtr world = small_world();
  el_bytes* raw = nullptr;
  ASSERT_EQ(el_landscape_save(world.get(), &raw, nullptr), EL_OK);
  const std::string expected = text_of(BytesPtr(raw).get());
  expect_made<BytesPtr>(
      "el_landscape_save",
      [&](el_bytes** out, el_error* e) { return el_landscape_save(world.get(), out, e); }, text_of,
      expected);
}

TEST(CapiOutOfMemory, LandscapeLoad) {
  const LandscapePtr world = small_world();
  const std::uint64_t world_hash = hash_of(world.get());
  el_bytes* raw = nullptr;
  ASSERT_EQ(el_landscape_save(world.get(), &raw, nullptr), EL_OK);
  const std::string save = text_of(BytesPtr(raw).get());
  const auto* data = reinterpret_cast<const std::uint8_t*>(save.data());
  expect_made<LandscapePtr>(
      "el_landscape_load",
      [&](el_landscape** out, el_error* e) {
        return el_landscape_load(data, save.size(), nullptr, out, e);
      },
      hash_of, world_hash, AlsoAccepted::kLoadErrorOutOfMemory);
}

// ---- shapes from anywhere, edit logs ------------------------------------------------------------

// A bow tie (two triangles) and a square with a square hole (hole-free pieces).
TEST(CapiOutOfMemory, ShapeImport) {
  const std::int64_t xy[] = {0,   0,  100, 100, 100, 0,   0,   100,  // the bow tie
                             200, 0,  400, 0,   400, 200, 200, 200,  // the square
                             250, 50, 250, 150, 350, 150, 350, 50};  // its hole, clockwise
  const std::uint32_t ring_offsets[] = {0, 4, 8, 12};
  const std::uint32_t polygon_rings[] = {0, 1, 3};
  el_shape* raw = nullptr;
  ASSERT_EQ(el_shape_import(xy, ring_offsets, polygon_rings, 2, &raw, nullptr), EL_OK);
  const std::vector<std::int64_t> expected = polygons_of(ShapePtr(raw).get());
  ASSERT_GT(expected.size(), 4u);
  expect_made<ShapePtr>(
      "el_shape_import",
      [&](el_shape** out, el_error* e) {
        return el_shape_import(xy, ring_offsets, polygon_rings, 2, out, e);
      },
      polygons_of, expected);
}

// What a replay did: its edits, why it stopped (status and line) and its landscape's hash.
struct ReplayResult {
  std::size_t edits = 0;
  el_status stopped = EL_OK;
  std::uint64_t line = 0;
  std::uint64_t hash = 0;
  bool operator==(const ReplayResult&) const = default;
};

ReplayResult result_of(const el_replay* replay) {
  ReplayResult r;
  r.edits = el_replay_edits(replay);
  el_error error;
  el_error_init(&error);
  r.stopped = el_replay_stopped(replay, &error);
  r.line = error.index;
  el_landscape* raw = nullptr;
  EXPECT_EQ(el_replay_landscape(replay, &raw, nullptr), EL_OK);
  r.hash = hash_of(LandscapePtr(raw).get());
  return r;
}

// A log recorded through the C API, with a bad line after its edits: the replay runs the edits
// and the stop.
std::string recorded_log() {
  const el_landscape_config config = cells_config();
  el_landscape* raw = nullptr;
  EXPECT_EQ(el_landscape_create(&kWorld, 1, &config, &raw, nullptr), EL_OK);
  const LandscapePtr world(raw);
  EXPECT_EQ(el_landscape_start_log(world.get(), nullptr), EL_OK);
  EXPECT_EQ(el_landscape_carve(world.get(), circle_shape(512, 256, 120).get(), nullptr, nullptr),
            EL_OK);
  EXPECT_EQ(el_landscape_fill(world.get(), circle_shape(512, 256, 40).get(), 2, nullptr, nullptr),
            EL_OK);
  el_bytes* log = nullptr;
  EXPECT_EQ(el_landscape_log(world.get(), &log, nullptr), EL_OK);
  return text_of(BytesPtr(log).get()) + "fill 300 POLYGON((0 0,10 0,10 10,0 10))\n";
}

TEST(CapiOutOfMemory, ReplayLog) {
  const std::string log = recorded_log();
  el_replay* raw = nullptr;
  ASSERT_EQ(el_replay_log(log.data(), log.size(), &raw, nullptr), EL_OK);
  const ReplayResult expected = result_of(ReplayPtr(raw).get());
  ASSERT_EQ(expected.edits, 2u);
  ASSERT_EQ(expected.stopped, EL_LOAD_ERROR);
  expect_made<ReplayPtr>(
      "el_replay_log",
      [&](el_replay** out, el_error* e) { return el_replay_log(log.data(), log.size(), out, e); },
      [](const el_replay* r) { return result_of(r); }, expected);
}

// ---- the game driver ----------------------------------------------------------------------------

std::uint64_t driver_hash(const el_game_driver* driver) {
  el_landscape* raw = nullptr;
  EXPECT_EQ(el_game_driver_landscape(driver, &raw, nullptr), EL_OK);
  return hash_of(LandscapePtr(raw).get());
}

DriverPtr driver_of(const el_landscape* world) {
  el_game_driver* raw = nullptr;
  EXPECT_EQ(el_game_driver_create(world, nullptr, &raw, nullptr), EL_OK);
  return DriverPtr(raw);
}

TEST(CapiOutOfMemory, GameDriverCreate) {
  const LandscapePtr world = small_world();
  const std::uint64_t world_hash = hash_of(world.get());
  expect_made<DriverPtr>(
      "el_game_driver_create",
      [&](el_game_driver** out, el_error* e) {
        return el_game_driver_create(world.get(), nullptr, out, e);
      },
      driver_hash, world_hash);
}

// Adding an edit to a batch: a failure leaves the batch as it was.
TEST(CapiOutOfMemory, EditsFill) {
  const ShapePtr rock = circle_shape(200, 400, 30);
  for_each_fault("el_edits_fill", [&](std::size_t skip, FaultMode mode) {
    el_edits* raw = nullptr;
    EXPECT_EQ(el_edits_create(&raw, nullptr), EL_OK);
    const EditsPtr edits(raw);
    EXPECT_EQ(el_edits_carve(edits.get(), rock.get(), nullptr), EL_OK);
    const Outcome o = with_fault(
        skip, mode, [&](el_error* e) { return el_edits_fill(edits.get(), rock.get(), 2, e); });
    EXPECT_EQ(el_edits_count(edits.get()), failed(o) ? 1u : 2u);
    return o;
  });
}

// What an update and the driver after it hold, ids aside (a reset driver numbers its chains on).
struct UpdateResult {
  std::uint64_t landscape = 0;
  std::size_t removed = 0, added = 0, chains = 0, chain_points = 0, meshes = 0, debris = 0;
  std::vector<std::uint64_t> debris_areas;
  bool operator==(const UpdateResult&) const = default;
};

UpdateResult result_of(const el_game_driver* driver, const el_game_update* update) {
  UpdateResult r;
  r.landscape = driver_hash(driver);
  const el_changes* changes = el_game_update_changes(update);
  r.removed = removed_count(changes);
  r.added = el_polygons_count(el_changes_added(changes));
  el_chains* raw = nullptr;
  EXPECT_EQ(el_game_driver_chains(driver, &raw, nullptr), EL_OK);
  const std::unique_ptr<el_chains, Destroyer<el_chains, el_chains_destroy>> chains(raw);
  el_chains_info(chains.get(), &r.chains);
  el_chains_points(chains.get(), &r.chain_points);
  r.meshes = el_polygons_count(el_meshes_polygons(el_game_update_meshes(update)));
  const el_debris_info* debris = el_game_update_debris(update, &r.debris);
  for (std::size_t i = 0; i < r.debris; ++i) r.debris_areas.push_back(debris[i].twice_area.lo);
  return r;
}

// The ids of a chain list's chains, ascending.
std::vector<std::uint64_t> chain_ids(const el_chains* chains) {
  std::size_t n = 0;
  const el_chain_info* info = el_chains_info(chains, &n);
  std::vector<std::uint64_t> ids;
  for (std::size_t i = 0; i < n; ++i) ids.push_back(info[i].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::uint64_t> driver_chain_ids(const el_game_driver* driver) {
  el_chains* all = nullptr;
  EXPECT_EQ(el_game_driver_chains(driver, &all, nullptr), EL_OK);
  const std::vector<std::uint64_t> ids = chain_ids(all);
  el_chains_destroy(all);
  return ids;
}

// A game's chains after it applies a reset's update to those it held: every removed id was
// held, no added id was, and the result is the driver's chains. The game's copy is what it was
// told before the failed apply (that apply returned no update).
void expect_reset_takes_the_game_along(std::vector<std::uint64_t> held, const el_game_update* reset,
                                       const el_game_driver* driver) {
  const el_chains* chains = el_game_update_chains(reset);
  std::size_t removed_count = 0;
  const std::uint64_t* removed = el_chains_removed(chains, &removed_count);
  for (std::size_t i = 0; i < removed_count; ++i) {
    const auto at = std::find(held.begin(), held.end(), removed[i]);
    EXPECT_NE(at, held.end()) << "the reset removes chain " << removed[i] << ", never given";
    if (at != held.end()) held.erase(at);
  }
  for (std::uint64_t id : chain_ids(chains)) {
    EXPECT_EQ(std::find(held.begin(), held.end(), id), held.end()) << "chain " << id << " twice";
    held.push_back(id);
  }
  std::sort(held.begin(), held.end());
  EXPECT_EQ(held, driver_chain_ids(driver));
}

// How a run whose apply failed carries on.
enum class Recovery {
  kNewDriver,  // the driver destroyed (a leak on the failure path shows here) and made anew
  kReset,      // the driver reset to the world, as edgeland.h asks after EL_OUT_OF_MEMORY
};

// One frame's batch: a crater in the ground that cuts the ore vein free, and a rock filled in
// the air; both fall as debris, with convex pieces and meshes (the world has no island of its
// own, so a reset detaches nothing). Every run leaves the caller's world and batch as they were,
// and after a failure the same batch on the recovered driver gives the update of a driver that
// never failed.
void apply_with_faults(Recovery recovery) {
  const LandscapePtr world = ground_world(2);  // 4 x 4 cells: a driver is made for every run
  const std::uint64_t world_hash = hash_of(world.get());
  const ShapePtr crater = circle_shape(300, 150, 75);
  const ShapePtr vein = circle_shape(300, 150, 55);
  const ShapePtr rock = box_shape(800, 400, 840, 440);
  el_edits* raw = nullptr;
  ASSERT_EQ(el_edits_create(&raw, nullptr), EL_OK);
  const EditsPtr edits(raw);
  ASSERT_EQ(el_edits_carve(edits.get(), crater.get(), nullptr), EL_OK);
  ASSERT_EQ(el_edits_fill(edits.get(), vein.get(), 2, nullptr), EL_OK);
  ASSERT_EQ(el_edits_fill(edits.get(), rock.get(), 4, nullptr), EL_OK);
  UpdateResult expected;
  {
    const DriverPtr driver = driver_of(world.get());
    el_game_update* out = nullptr;
    ASSERT_EQ(el_game_driver_apply(driver.get(), edits.get(), &out, nullptr), EL_OK);
    expected = result_of(driver.get(), UpdatePtr(out).get());
    ASSERT_GE(expected.debris, 2u);
  }
  for_each_fault("el_game_driver_apply", [&](std::size_t skip, FaultMode mode) {
    DriverPtr driver = driver_of(world.get());
    const std::vector<std::uint64_t> held = driver_chain_ids(driver.get());
    el_game_update* out = nullptr;
    const Outcome o = with_fault(skip, mode, [&](el_error* e) {
      return el_game_driver_apply(driver.get(), edits.get(), &out, e);
    });
    UpdatePtr update(out);
    EXPECT_EQ(hash_of(world.get()), world_hash);
    EXPECT_EQ(el_edits_count(edits.get()), 3u);
    if (failed(o)) {
      EXPECT_EQ(out, nullptr);
      if (recovery == Recovery::kReset) {
        el_game_update* reset = nullptr;
        EXPECT_EQ(el_game_driver_reset(driver.get(), world.get(), &reset, nullptr), EL_OK);
        const UpdatePtr reset_update(reset);
        EXPECT_EQ(driver_hash(driver.get()), world_hash);
        if (reset_update) expect_reset_takes_the_game_along(held, reset_update.get(), driver.get());
      } else {
        driver = driver_of(world.get());
      }
      EXPECT_EQ(el_game_driver_apply(driver.get(), edits.get(), &out, nullptr), EL_OK);
      update.reset(out);
    }
    EXPECT_TRUE(result_of(driver.get(), update.get()) == expected);
    return o;
  });
}

TEST(CapiOutOfMemory, GameDriverApply) { apply_with_faults(Recovery::kNewDriver); }

// The reset edgeland.h prescribes after EL_OUT_OF_MEMORY from apply: the driver derives
// everything anew from the world, and the reset's update takes the game from the chains it held
// to the driver's. (Before the driver kept what it had delivered, this crashed: the failed apply
// left the cell store and the surface state half changed, and reset read them.)
TEST(CapiOutOfMemory, GameDriverResetAfterApplyFails) { apply_with_faults(Recovery::kReset); }

}  // namespace
