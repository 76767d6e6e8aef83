// edgeland_landscape_profile: one landscape edit workload (landscape_workloads.hpp) run for its
// figures per edit rather than its time: the cells each edit touches (cells whose box interior
// meets the shape's box), the heap allocations each edit makes (global operator new counted),
// and, under callgrind, the instructions of the edits alone (collection is switched on around
// each edit only):
//
//   valgrind --tool=callgrind --collect-atstart=no edgeland_landscape_profile carve --edits 2000
//
// Instructions per touched cell = callgrind's total / the touched cells printed here. The fill
// workload runs the carve workload first, uncounted (its start world). Options: --tree
// quadtree|kdtree|grid, --edits N (default 2000), --skip N (edits applied uncounted first).
//
// Big shapes (landscape_big_shapes.hpp): `combs-fill` fills the comb set of --vertices N
// (default 10000) into an empty 4096 x 4096 world, `combs-back` carves it back out of the
// filled world (the fill uncounted): one edit each.
#include <valgrind/callgrind.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "landscape_big_shapes.hpp"
#include "landscape_workloads.hpp"

namespace {

std::atomic<std::size_t> allocations{0};

}  // namespace

void* operator new(std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace edgeland::bench {
namespace {

struct Options {
  Workload workload = Workload::kCarve;
  Rival rival = Rival::kQuadtree;
  std::size_t edits = 2000, skip = 0;
  // Big shapes: 0 none, 1 the comb set's fill, 2 its carve back.
  int combs = 0;
  std::size_t vertices = 10000;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(
      stderr,
      "edgeland_landscape_profile: %s\nusage: edgeland_landscape_profile "
      "carve|dig|fill|spot|pit|combs-fill|combs-back [--tree quadtree|kdtree|grid] [--edits N] "
      "[--skip N] [--vertices N]\n",
      why.c_str());
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  if (argc < 2) usage("no workload");
  const std::string name = argv[1];
  o.combs = name == "combs-fill" ? 1 : name == "combs-back" ? 2 : 0;
  const auto w = workload_named(name);
  if (!w && o.combs == 0) usage("unknown workload " + name);
  if (w) o.workload = *w;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--tree") {
      const auto r = rival_named(value);
      if (!r || *r == Rival::kBitmap) usage("unknown tree " + value);
      o.rival = *r;
    } else if (flag == "--edits") {
      o.edits = std::stoul(value);
    } else if (flag == "--skip") {
      o.skip = std::stoul(value);
    } else if (flag == "--vertices") {
      o.vertices = std::stoul(value);
    } else {
      usage("unknown option " + flag);
    }
  }
  if (argc % 2 != 0) usage("an option without its value");
  return o;
}

// The cells an edit with this shape descends into (spatial/src/edit.cpp: box interiors meet).
std::size_t touched_cells(const Landscape& l, const ValidSet& shape) {
  const auto box = bounding_box(shape.polygons());
  if (!box) return 0;
  std::size_t n = 0;
  l.cells_in(*box, [&](const CellView& c) {
    const Box64& b = c.box;
    n += b.min.x < box->max.x && box->min.x < b.max.x && b.min.y < box->max.y &&
         box->min.y < b.max.y;
    return true;
  });
  return n;
}

// One edit of the comb set (landscape_big_shapes.hpp): its fill, or its carve back.
int run_combs(const Options& o) {
  const ValidSet shape = comb_set(o.vertices);
  World world = make_world(o.rival, kBigShapeWorld, kEmpty);
  if (o.combs == 2) apply(world, EditKind::kFill, shape, 1);
  const std::size_t cells = touched_cells(std::get<Landscape>(world), shape);
  const std::size_t before = allocations.load();
  CALLGRIND_TOGGLE_COLLECT;
  const double seconds = seconds_of([&] {
    apply(world, o.combs == 1 ? EditKind::kFill : EditKind::kCarve, shape, o.combs == 1 ? 1 : 0);
  });
  CALLGRIND_TOGGLE_COLLECT;
  const auto& l = std::get<Landscape>(world);
  const LandscapeStats s = l.stats();
  std::printf("comb set of %zu vertices, %s, %s\n", o.vertices,
              o.combs == 1 ? "fill" : "carve back", rival_name(o.rival));
  std::printf("touched cells %zu, allocations %zu, time %.1f ms (not under valgrind)\n", cells,
              allocations.load() - before, seconds * 1e3);
  std::printf("end: %zu polygons, %zu vertices, %zu cells, check %s\n", s.polygons, s.vertices,
              s.cells, l.check().ok() ? "ok" : "FAILED");
  return 0;
}

int run(const Options& o) {
  if (o.combs != 0) return run_combs(o);
  World world = make_world(o.rival, kEditWorld, 1);
  if (o.workload == Workload::kFill)
    for (const Edit& e : workload_edits(Workload::kCarve, 10000)) apply_edit(world, e);
  const std::vector<Edit> edits = workload_edits(o.workload, o.skip + o.edits);
  for (std::size_t i = 0; i < o.skip; ++i) apply_edit(world, edits[i]);
  std::size_t cells = 0, allocated = 0;
  double seconds = 0;
  for (std::size_t i = o.skip; i < edits.size(); ++i) {
    cells += touched_cells(std::get<Landscape>(world), edits[i].shape);
    const std::size_t before = allocations.load();
    CALLGRIND_TOGGLE_COLLECT;
    seconds += seconds_of([&] { apply_edit(world, edits[i]); });
    CALLGRIND_TOGGLE_COLLECT;
    allocated += allocations.load() - before;
  }
  const auto& l = std::get<Landscape>(world);
  const LandscapeStats s = l.stats();
  const double n = static_cast<double>(o.edits);
  std::printf("workload %s, %s, %zu edits after %zu\n", workload_name(o.workload),
              rival_name(o.rival), o.edits, o.skip);
  std::printf("touched cells %zu (%.3f per edit)\n", cells, static_cast<double>(cells) / n);
  std::printf("allocations %zu (%.1f per edit, %.1f per touched cell)\n", allocated,
              static_cast<double>(allocated) / n,
              static_cast<double>(allocated) / static_cast<double>(cells));
  std::printf("time %.1f us per edit (wall clock; not under valgrind)\n", seconds * 1e6 / n);
  std::printf("end: %zu polygons, %zu vertices, %zu cells, check %s\n", s.polygons, s.vertices,
              s.cells, l.check().ok() ? "ok" : "FAILED");
  return 0;
}

}  // namespace
}  // namespace edgeland::bench

int main(int argc, char** argv) { return edgeland::bench::run(edgeland::bench::parse(argc, argv)); }
