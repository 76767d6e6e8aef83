// Queries on a cave terrain (thesis chapter 5: "a collision check is much faster in a
// pixel-based landscape"): an 8192 x 8192 world of material 1 with CAVES circles carved
// (radii 24-160, EDGELAND_LANDSCAPE_CAVES, default 300), asked at QUERIES seeded random places
// (EDGELAND_LANDSCAPE_QUERIES, default 10000):
//
//   material_at: a point anywhere; the bitmap reads one byte (from DRAM: 64 MiB, random places).
//   material_at_walk: the points of a random walk, 3 units a step (a character's feet): the
//                bitmap's bytes and the landscape's cells stay in the cache.
//   raycast:     200 units from a point in empty space in a random direction (both ends in the
//                world); the bitmap walks the squares (integer DDA); Box2D 2.4 casts against the
//                same terrain loaded as static chain loops (b2World::RayCast, closest hit).
//   overlaps:    a character-sized 16 x 32 box anywhere (Landscape::overlaps(Box64)); the
//                bitmap scans its 512 bytes; Box2D runs b2World::QueryAABB with a callback that
//                counts the chain edges whose fattened boxes meet it.
//
// Time per query: the median over batches of 64 queries, each batch the fastest of REPEATS
// passes (landscape_common.hpp, batch_seconds). Ratios X_vs_bitmap and
// X_vs_box2d divide by the median of the other contender, measured in the same process. The
// answers are compared too (agree_*): the bitmap knows the terrain only square by square.
#include <box2d/box2d.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "landscape_common.hpp"
#include "landscape_shapes.hpp"

namespace edgeland::bench {
namespace {

constexpr std::int64_t kSide = 8192;
constexpr Box64 kWorld{{0, 0}, {kSide, kSide}};
constexpr double kRayLength = 200;
// Box2D is tuned for objects of 0.1-10 m: 16 units to the metre makes the 16 x 32 character
// 1 x 2 m, and the shortest terrain edge (1 unit) still 12x Box2D's linear slop.
constexpr float kMetresPerUnit = 1.0f / 16.0f;

enum class Query : std::uint8_t { kMaterialAt, kMaterialAtWalk, kRaycast, kOverlaps };
const char* query_name(Query q) {
  switch (q) {
    case Query::kMaterialAt:
      return "material_at";
    case Query::kMaterialAtWalk:
      return "material_at_walk";
    case Query::kRaycast:
      return "raycast";
    case Query::kOverlaps:
      return "overlaps";
  }
  return "?";
}

std::size_t query_count() { return env_count("EDGELAND_LANDSCAPE_QUERIES", 10000); }

const World& terrain(Rival rival) {
  static std::map<Rival, World> cache;
  auto it = cache.find(rival);
  if (it == cache.end()) {
    World world = make_world(rival, kWorld, 1);
    for (const ValidSet& cave :
         as_shapes(caves(0xCA7E, env_count("EDGELAND_LANDSCAPE_CAVES", 300), kWorld)))
      apply(world, EditKind::kCarve, cave, kEmpty);
    it = cache.emplace(rival, std::move(world)).first;
  }
  return it->second;
}

// The terrain in Box2D: every landscape polygon a static chain loop. Polygons are cut at the
// landscape's cell lines (and holes split by bridges), so the loops include those seam edges,
// which a ray from empty space reaches only after a real surface; a level exported for Box2D
// by hand would merge them away, which would give Box2D fewer edges than it has here.
struct Box2dTerrain {
  std::unique_ptr<b2World> world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  std::size_t loops = 0, edges = 0;
};

b2Vec2 to_box2d(Point64 p) {
  return {static_cast<float>(p.x) * kMetresPerUnit, static_cast<float>(p.y) * kMetresPerUnit};
}

const Box2dTerrain& box2d_terrain() {
  static std::optional<Box2dTerrain> cache;
  if (cache) return *cache;
  cache.emplace();
  b2BodyDef def;  // static by default
  b2Body* body = cache->world->CreateBody(&def);
  std::vector<b2Vec2> vertices;
  std::get<Landscape>(terrain(Rival::kQuadtree)).polygons_in(kWorld, [&](const PolygonView& v) {
    vertices.clear();
    for (const Point64& p : *v.polygon) vertices.push_back(to_box2d(p));
    b2ChainShape chain;
    chain.CreateLoop(vertices.data(), static_cast<int32>(vertices.size()));
    body->CreateFixture(&chain, 0.0f);
    ++cache->loops;
    cache->edges += vertices.size();
    return true;
  });
  return *cache;
}

struct Ray {
  Point64 from, to;
};

// Seeded rays of kRayLength from empty points (by the landscape's material_at) into random
// directions, both ends inside the world.
const std::vector<Ray>& rays() {
  static std::vector<Ray> cache;
  if (!cache.empty()) return cache;
  const Landscape& l = std::get<Landscape>(terrain(Rival::kQuadtree));
  SplitMix64 random(0x4A7C);
  while (cache.size() < query_count()) {
    const Point64 from = random_points(random.next(), 1, kWorld).front();
    const double angle = 2.0 * 3.14159265358979323846 * unit_draw(random);
    const Point64 to{from.x + std::llround(kRayLength * std::cos(angle)),
                     from.y + std::llround(kRayLength * std::sin(angle))};
    if (!kWorld.contains(to) || l.material_at(from) != kEmpty) continue;
    cache.push_back({from, to});
  }
  return cache;
}

const std::vector<Point64>& points() {
  static const std::vector<Point64> cache = random_points(0x9017, query_count(), inset(kWorld, 1));
  return cache;
}

const std::vector<Point64>& walk() {
  static const std::vector<Point64> cache =
      random_walk(0x3A1C, query_count() - 1, 3.0, inset(kWorld, 16));
  return cache;
}

const std::vector<Point64>& points(Query q) { return q == Query::kMaterialAt ? points() : walk(); }

const std::vector<Box64>& boxes() {
  static std::vector<Box64> cache;
  if (cache.empty())
    for (const Point64& p :
         random_points(0xB0C5, query_count(), {{0, 0}, {kSide - 16, kSide - 32}}))
      cache.push_back({p, {p.x + 16, p.y + 32}});
  return cache;
}

// One answer per query, comparable between contenders: the material, the distance to the hit
// (-1: none) or whether anything overlaps.
struct QueryRun {
  std::vector<double> batch_seconds;  // per query, fastest pass of each batch
  std::vector<double> answers;
};

template <class Ask>
QueryRun run_batches(std::size_t n, Ask&& ask) {
  QueryRun run;
  run.answers.resize(n);
  run.batch_seconds = batch_seconds(n, [&](std::size_t i) { run.answers[i] = ask(i); });
  benchmark::DoNotOptimize(run.answers.data());
  return run;
}

// Distance along the ray to a hit, -1 for none: the landscape's exact t, the bitmap's square.
double hit_distance(const std::optional<MaterialCrossing>& hit) {
  if (!hit) return -1.0;
  return kRayLength * static_cast<double>(hit->t.num) / static_cast<double>(hit->t.den);
}
double hit_distance(const std::optional<BitmapHit>& hit) {
  if (!hit) return -1.0;
  return kRayLength * static_cast<double>(hit->t_num) / static_cast<double>(hit->t_den);
}

// A landscape or the bitmap: the same member names answer the same questions.
template <class W>
QueryRun run_world(Query q, const W& w) {
  if (q == Query::kMaterialAt || q == Query::kMaterialAtWalk) {
    const std::vector<Point64>& p = points(q);
    return run_batches(p.size(),
                       [&](std::size_t i) { return double(w.material_at(p[i]).value()); });
  }
  if (q == Query::kOverlaps)
    return run_batches(boxes().size(),
                       [&](std::size_t i) { return double(!w.overlaps(boxes()[i]).empty()); });
  return run_batches(rays().size(), [&](std::size_t i) {
    return hit_distance(w.raycast(rays()[i].from, rays()[i].to));
  });
}

struct ClosestHit final : b2RayCastCallback {
  float fraction = -1.0f;
  float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float f) override {
    fraction = f;
    return f;  // clip the ray: later reports are closer
  }
};

struct CountEdges final : b2QueryCallback {
  std::size_t count = 0;
  bool ReportFixture(b2Fixture*) override {
    ++count;
    return true;
  }
};

QueryRun run_box2d(Query q) {
  const b2World& world = *box2d_terrain().world;
  if (q == Query::kRaycast) {
    return run_batches(rays().size(), [&](std::size_t i) {
      ClosestHit hit;
      world.RayCast(&hit, to_box2d(rays()[i].from), to_box2d(rays()[i].to));
      return hit.fraction < 0 ? -1.0 : kRayLength * double(hit.fraction);
    });
  }
  return run_batches(boxes().size(), [&](std::size_t i) {
    CountEdges edges;
    b2AABB box;
    box.lowerBound = to_box2d(boxes()[i].min);
    box.upperBound = to_box2d(boxes()[i].max);
    world.QueryAABB(&edges, box);
    return double(edges.count > 0);
  });
}

// The contenders: a rival's terrain or "box2d".
QueryRun run_query(Query q, const std::string& who) {
  if (who == "box2d") return run_box2d(q);
  return std::visit([q](const auto& w) { return run_world(q, w); }, terrain(*rival_named(who)));
}

// Runs of each (query, contender), kept for the ratios and the agreement counters.
const QueryRun& result(Query q, const std::string& who, bool fresh) {
  static std::map<std::pair<Query, std::string>, QueryRun> cache;
  const auto key = std::make_pair(q, who);
  auto it = cache.find(key);
  if (fresh || it == cache.end()) it = cache.insert_or_assign(key, run_query(q, who)).first;
  return it->second;
}

// Fraction of queries whose answers agree: same material, same hit/miss (and, both hitting,
// within `tolerance` units), same overlap verdict.
double agreement(const QueryRun& a, const QueryRun& b, double tolerance) {
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.answers.size(); ++i) {
    const double x = a.answers[i], y = b.answers[i];
    if ((x < 0) == (y < 0) && std::abs(x - y) <= tolerance) ++same;
  }
  return a.answers.empty() ? 1.0
                           : static_cast<double>(same) / static_cast<double>(a.answers.size());
}

void compare_with(benchmark::State& state, Query q, const QueryRun& mine, const std::string& other,
                  double median_ns) {
  const QueryRun& theirs = result(q, other, false);
  state.counters["median_vs_" + other] = median_ns / (quantile(theirs.batch_seconds, 0.5) * 1e9);
  // Rays: within 2 units (squares vs exact edges, float vs integers) counts as the same hit.
  state.counters["agree_" + other] = agreement(mine, theirs, q == Query::kRaycast ? 2.0 : 0.0);
}

void run_query_benchmark(benchmark::State& state, Query q, const std::string& who) {
  const QueryRun* run = nullptr;
  for (auto _ : state) {
    if (!guarded(state, [&] { run = &result(q, who, true); })) return;
    double total = 0;
    for (double s : run->batch_seconds) total += s * kQueryBatch;
    state.SetIterationTime(total);
  }
  const double median_ns = quantile(run->batch_seconds, 0.5) * 1e9;
  state.counters["median_ns"] = median_ns;
  std::size_t answered = 0;
  for (double a : run->answers) answered += a > 0 ? 1 : 0;
  state.counters["nonzero_answers"] =
      static_cast<double>(answered) / static_cast<double>(run->answers.size());
  if (who == "box2d") {
    state.counters["chain_loops"] = static_cast<double>(box2d_terrain().loops);
    state.counters["chain_edges"] = static_cast<double>(box2d_terrain().edges);
  } else if (!verify(state, terrain(*rival_named(who)))) {
    return;
  }
  guarded(state, [&] {
    if (who != "bitmap") compare_with(state, q, *run, "bitmap", median_ns);
    if (who != "box2d" && who != "bitmap" && (q == Query::kRaycast || q == Query::kOverlaps))
      compare_with(state, q, *run, "box2d", median_ns);
  });
}

}  // namespace

void register_query_benchmarks() {
  for (Query q : {Query::kMaterialAt, Query::kMaterialAtWalk, Query::kRaycast, Query::kOverlaps}) {
    std::vector<std::string> who{"bitmap"};
    if (q == Query::kRaycast || q == Query::kOverlaps) who.push_back("box2d");
    for (const char* r : {"quadtree", "kdtree", "grid"}) who.push_back(r);
    for (const std::string& w : who) {
      const std::string name = std::string("landscape_query/") + query_name(q) + "/" + w;
      benchmark::RegisterBenchmark(
          name.c_str(), [q, w](benchmark::State& state) { run_query_benchmark(state, q, w); })
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace edgeland::bench
