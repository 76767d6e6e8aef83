#include "landscape_common.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace edgeland::bench {

double env_number(const char* name, double fallback) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return fallback;
  return std::strtod(value, nullptr);
}

std::size_t env_count(const char* name, std::size_t fallback) {
  return static_cast<std::size_t>(env_number(name, static_cast<double>(fallback)));
}

const char* rival_name(Rival rival) {
  switch (rival) {
    case Rival::kQuadtree:
      return "quadtree";
    case Rival::kKdTree:
      return "kdtree";
    case Rival::kGrid:
      return "grid";
    case Rival::kBitmap:
      return "bitmap";
  }
  return "?";
}

std::optional<Rival> rival_named(const std::string& name) {
  for (Rival r : {Rival::kQuadtree, Rival::kKdTree, Rival::kGrid, Rival::kBitmap})
    if (name == rival_name(r)) return r;
  return std::nullopt;
}

LandscapeConfig landscape_config(Rival rival, std::int64_t world_side) {
  LandscapeConfig config;
  // Cell size experiments (issue 35 point 6): the adaptive trees' split threshold and smallest
  // cell from the environment, the library's defaults otherwise.
  config.edge_cap =
      static_cast<std::uint32_t>(env_count("EDGELAND_LANDSCAPE_EDGE_CAP", config.edge_cap));
  config.merge_below =
      static_cast<std::uint32_t>(env_count("EDGELAND_LANDSCAPE_MERGE_BELOW", config.merge_below));
  config.min_cell_size = static_cast<std::int64_t>(
      env_count("EDGELAND_LANDSCAPE_MIN_CELL", static_cast<std::size_t>(config.min_cell_size)));
  if (rival == Rival::kKdTree) config.tree = TreeKind::kKdTree;
  if (rival == Rival::kGrid) {
    config.grid_depth = 0;
    for (std::int64_t side = world_side; side > kGridCell; side /= 2) ++config.grid_depth;
  }
  return config;
}

World make_world(Rival rival, const Box64& box, Material fill) {
  if (rival == Rival::kBitmap) return World(std::in_place_type<BitmapWorld>, box, fill);
  return World(std::in_place_type<Landscape>, box, fill,
               landscape_config(rival, box.max.x - box.min.x));
}

void apply(World& world, EditKind kind, const ValidSet& shape, Material material, Material from) {
  if (auto* l = std::get_if<Landscape>(&world)) {
    if (kind == EditKind::kCarve)
      l->carve(shape);
    else if (kind == EditKind::kFill)
      l->fill(shape, material);
    else
      l->replace(shape, from, material);
    return;
  }
  auto& b = std::get<BitmapWorld>(world);
  if (kind == EditKind::kReplace)
    b.replace(shape.polygons(), from, material);
  else
    b.paint(shape.polygons(), kind == EditKind::kCarve ? kEmpty : material);
}

Material material_at(const World& world, Point64 p) {
  return std::visit([p](const auto& w) { return w.material_at(p); }, world);
}

bool is_landscape(const World& world) { return std::holds_alternative<Landscape>(world); }

std::vector<Edit> edits_of(EditKind kind, const std::vector<ValidSet>& shapes, Material material) {
  std::vector<Edit> out;
  out.reserve(shapes.size());
  for (const ValidSet& shape : shapes) out.push_back({shape, kind, material});
  return out;
}

std::vector<double> time_edits(World& world, const std::vector<Edit>& edits) {
  std::vector<double> seconds;
  seconds.reserve(edits.size());
  for (const Edit& e : edits) seconds.push_back(seconds_of([&] { apply_edit(world, e); }));
  return seconds;
}

namespace {

// A workload's edit as the landscape's Edit (types.hpp), for a batch.
edgeland::Edit landscape_edit(const Edit& e) {
  switch (e.kind) {
    case EditKind::kCarve:
      return edgeland::Edit::carve(e.shape);
    case EditKind::kFill:
      return edgeland::Edit::fill(e.shape, e.material);
    case EditKind::kReplace:
      break;
  }
  return edgeland::Edit::replace(e.shape, e.from, e.material);
}

// The edits [from, to) as one batch: made before the clock starts.
double time_batch(World& world, const std::vector<Edit>& edits, std::size_t from, std::size_t to) {
  if (auto* l = std::get_if<Landscape>(&world)) {
    std::vector<edgeland::Edit> batch;
    for (std::size_t i = from; i < to; ++i) batch.push_back(landscape_edit(edits[i]));
    return seconds_of([&] { l->apply_batch(batch); });
  }
  return seconds_of([&] {
    for (std::size_t i = from; i < to; ++i) apply_edit(world, edits[i]);
  });
}

}  // namespace

std::vector<double> time_batches(World& world, const std::vector<Edit>& edits, std::size_t size) {
  if (size <= 1) return time_edits(world, edits);
  std::vector<double> seconds;
  for (std::size_t from = 0; from < edits.size(); from += size)
    seconds.push_back(time_batch(world, edits, from, std::min(from + size, edits.size())));
  return seconds;
}

std::size_t repeats() {
  return std::max<std::size_t>(1, env_count("EDGELAND_LANDSCAPE_REPEATS", 5));
}

std::vector<double> fastest_edits(const World& start, const std::vector<Edit>& edits,
                                  std::optional<World>& end, std::size_t batch) {
  std::vector<double> fastest;
  for (std::size_t r = 0; r < repeats(); ++r) {
    end.emplace(start);
    const std::vector<double> seconds = time_batches(*end, edits, batch);
    if (r == 0) fastest = seconds;
    for (std::size_t i = 0; i < seconds.size(); ++i) fastest[i] = std::min(fastest[i], seconds[i]);
  }
  return fastest;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  const auto rank = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

EditSummary summarize(const std::vector<double>& seconds, std::size_t block) {
  EditSummary s;
  s.median_us = quantile(seconds, 0.5) * 1e6;
  s.p99_us = quantile(seconds, 0.99) * 1e6;
  if (!seconds.empty())
    s.mean_us = std::accumulate(seconds.begin(), seconds.end(), 0.0) * 1e6 /
                static_cast<double>(seconds.size());
  for (std::size_t from = 0; block > 0 && from < seconds.size(); from += block) {
    const std::size_t to = std::min(from + block, seconds.size());
    s.block_median_us.push_back(quantile({seconds.begin() + static_cast<std::ptrdiff_t>(from),
                                          seconds.begin() + static_cast<std::ptrdiff_t>(to)},
                                         0.5) *
                                1e6);
  }
  return s;
}

void report(benchmark::State& state, const EditSummary& s, const std::string& prefix) {
  state.counters[prefix + "median_us"] = s.median_us;
  state.counters[prefix + "p99_us"] = s.p99_us;
  state.counters[prefix + "mean_us"] = s.mean_us;
  // Two-digit block numbers keep the counters in order in every output format.
  for (std::size_t b = 0; b < s.block_median_us.size(); ++b)
    state.counters[prefix + "block" + (b < 10 ? "0" : "") + std::to_string(b) + "_median_us"] =
        s.block_median_us[b];
  if (s.block_median_us.size() > 1 && s.block_median_us.front() > 0)
    state.counters[prefix + "flatness"] = s.block_median_us.back() / s.block_median_us.front();
}

void report_stats(benchmark::State& state, const World& world) {
  const auto* l = std::get_if<Landscape>(&world);
  if (l == nullptr) {
    state.counters["bytes"] = static_cast<double>(std::get<BitmapWorld>(world).bytes());
    return;
  }
  const LandscapeStats s = l->stats();
  state.counters["polygons"] = static_cast<double>(s.polygons);
  state.counters["vertices"] = static_cast<double>(s.vertices);
  state.counters["cells"] = static_cast<double>(s.cells);
  state.counters["depth"] = static_cast<double>(s.depth);
  state.counters["bytes"] = static_cast<double>(s.bytes);
  if (s.vertices > 0)
    state.counters["bytes_per_vertex"] =
        static_cast<double>(s.bytes) / static_cast<double>(s.vertices);
}

void fail(benchmark::State& state, const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  state.SkipWithError(message.c_str());
}

bool verify(benchmark::State& state, const World& world) {
  const auto* l = std::get_if<Landscape>(&world);
  if (l == nullptr) return true;
  const LandscapeReport r = l->check();
  if (r.ok()) return true;
  fail(state, "landscape check failed: " + std::to_string(r.problems.size()) +
                  " problems, first: " + r.problems.front());
  return false;
}

}  // namespace edgeland::bench
