// Closure chains (issue 4, "Verification"): the continuous-clip use of a game. A world - a
// 4 x 4 grid of cells sharing edges - is carved, filled, xor-ed and trimmed by thousands of
// small random tools, each output fed back as the next input. After every step:
//   * the output is valid (checked mode, and validate() again here);
//   * it meets the accuracy contract against the exact result of THIS step's inputs (the
//     previous output op the tool), including the 1.5-band bound on the symmetric difference;
//   * its area is tracked against the exact chain E_k = E_(k-1) op tool_k, run on the same
//     tools in exact arithmetic, within an accumulated bound. Per step, the output S differs
//     from the exact R only within 1.5 of the boundary of R (contract) and only within 2 of
//     the tool (locality), so area(S xor R) <= area of the 1.5-band of the boundary of
//     R * W, W = the tool's box grown by 4: 3 perimeter(R * W) + (9/4) pi cycles(R * W). That
//     is asserted each step; boolean operations with a fixed tool do not increase the area
//     of a symmetric difference, so |area(S_k) - area(E_k)| <= the sum of the step bounds.
// Length and seed: EDGELAND_CHAIN_STEPS (default 200), EDGELAND_CHAIN_SEED (default 1).
// The exact reference is CGAL 5.5's Polygon_set_2, which after a few hundred steps can fail its
// own arrangement precondition (number_of_outer_ccbs() == 1, cf. CGAL issue #644) on valid
// regions - in any of the oracle's computations, since whether it fails depends on the exact
// shapes (so on edgeland's outputs) and on the arrangement it runs in. The oracle then computes
// the same region another way, exactly (cgal_reference.cpp: rebuilt sets, halves either side of
// a vertical line, part by part, a set's members joined in two groups); the summary line counts
// those fallbacks. A failure past all of them ends the test naming the step and the computation
// (oracle() below): it reports the oracle, not edgeland.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "polygon_set_helpers.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {
namespace {

std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

// One computation of the exact oracle. Should CGAL fail even through the oracle's fallbacks, the
// exception (which ends the test) says at which step and in which computation: it reports the
// oracle, not edgeland.
template <class Compute>
auto oracle(std::uint64_t step, const char* what, Compute compute) {
  try {
    return compute();
  } catch (const std::exception& e) {
    throw std::runtime_error("step " + std::to_string(step) + ", oracle's " + what + ": " +
                             e.what());
  }
}

// The fallbacks the oracle used since `before`.
OracleFallbacks fallbacks_since(const OracleFallbacks& before) {
  const OracleFallbacks now = oracle_fallbacks();
  return {now.rebuilt - before.rebuilt, now.split - before.split,
          now.part_by_part - before.part_by_part, now.members_in_halves - before.members_in_halves};
}

Rational area(const PolygonSet& s) { return Rational(BigInt(to_string(twice_area(s)))) / 2; }

// Area bound of the 1.5-band around the boundary of r within the tool's box grown by 4.
Rational local_band(const ExactRegion& r, const Polygon& tool) {
  Box64 w = *bounding_box(tool);
  const Polygon window{{w.min.x - 4, w.min.y - 4},
                       {w.max.x + 4, w.min.y - 4},
                       {w.max.x + 4, w.max.y + 4},
                       {w.min.x - 4, w.max.y + 4}};
  const ExactRegion local = r.apply(ClipOp::kIntersection, ExactRegion::of(window));
  return 3 * Rational(local.perimeter_ceil()) +
         Rational(99, 14) * Rational(local.boundary_cycles());
}

class ToolMaker {
 public:
  explicit ToolMaker(std::uint64_t seed) : rng_(seed) {}

  std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng_);
  }

  // A small valid tool polygon near the world, of one of several degenerate-prone kinds.
  Polygon tool(const PolygonSet& world) {
    while (true) {
      const std::vector<Point64> verts = all_vertices(world);
      Point64 c{uniform(0, 512), uniform(0, 512)};
      if (!verts.empty() && uniform(0, 2) == 0)
        c = verts[static_cast<std::size_t>(uniform(0, std::int64_t(verts.size()) - 1))];
      const std::int64_t r = uniform(2, 30);
      Polygon p;
      switch (uniform(0, 4)) {
        case 0:
        case 1: {  // convex or star, sometimes through an existing vertex
          std::vector<Point64> pts;
          const int n = static_cast<int>(uniform(3, 14));
          for (int i = 0; i < n; ++i) pts.push_back({c.x + uniform(-r, r), c.y + uniform(-r, r)});
          if (uniform(0, 1)) pts.push_back(c);
          p = uniform(0, 1) ? convex_hull(pts) : star_polygon({c.x + 1, c.y}, pts);
          break;
        }
        case 2: {  // one-unit sliver (thesis fig. 22)
          const std::int64_t len = uniform(2, 4 * r), rise = uniform(-r, r);
          p = {{c.x, c.y}, {c.x + len, c.y + rise}, {c.x + len, c.y + rise + 1}, {c.x, c.y + 1}};
          break;
        }
        case 3: {  // rectangle from an existing vertex: collinear overlaps with the world
          const std::int64_t w = uniform(1, 2 * r), h = uniform(1, 2 * r);
          p = {c, {c.x + w, c.y}, {c.x + w, c.y + h}, {c.x, c.y + h}};
          break;
        }
        default: {  // needle triangle from an existing vertex
          p = make_ccw({c,
                        {c.x + uniform(-4 * r, 4 * r), c.y + uniform(-4 * r, 4 * r)},
                        {c.x + uniform(-4 * r, 4 * r), c.y + uniform(-4 * r, 4 * r)}});
          break;
        }
      }
      if (p.size() >= 3 && validate(p, 1).ok()) return p;
    }
  }

  ClipOp op() {
    const std::int64_t k = uniform(0, 99);
    return k < 55   ? ClipOp::kDifference
           : k < 80 ? ClipOp::kUnion
           : k < 95 ? ClipOp::kXor
                    : ClipOp::kIntersection;
  }

  // For intersection: a big convex polygon covering most of the world (it trims corners).
  Polygon trimmer() {
    std::vector<Point64> pts;
    for (int i = 0; i < 12; ++i) pts.push_back({uniform(-80, 592), uniform(-80, 592)});
    pts.push_back({-100, 256});
    pts.push_back({612, 256});
    pts.push_back({256, -100});
    pts.push_back({256, 612});
    return convex_hull(pts);
  }

 private:
  std::mt19937_64 rng_;
};

TEST(ClipClosureChain, ContinuousCarvingStaysValidAndTracksTheExactChain) {
  const std::uint64_t steps = env_or("EDGELAND_CHAIN_STEPS", 200);
  const std::uint64_t seed = env_or("EDGELAND_CHAIN_SEED", 1);
  ToolMaker maker(seed);
  std::vector<std::pair<int, int>> all;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) all.push_back({i, j});
  PolygonSet world = grid_cells({0, 0}, 128, all);
  ExactRegion world_exact = ExactRegion::of(world);  // region of the current output
  ExactRegion chain = world_exact;                   // E_k: the exact chain
  Rational accumulated = 0, measured = 0;
  std::size_t max_vertices = 0, snapped_steps = 0, holes = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const OracleFallbacks fallbacks_before = oracle_fallbacks();
  ContractOptions options;
  options.symmetric_difference_bound = false;  // done below, with the cached output region
  options.random_points = 40;

  for (std::uint64_t k = 1; k <= steps; ++k) {
    const ClipOp op = maker.op();
    const Polygon tool = op == ClipOp::kIntersection ? maker.trimmer() : maker.tool(world);
    const PolygonSet tools{tool};
    const Outcome o = run_clip(op, world, tools);
    ASSERT_TRUE(o.ok()) << "step " << k << ": " << o.error;
    const PolygonSet& next = o.result->polygons;
    const ValidationReport v = validate(next);
    ASSERT_TRUE(v.ok()) << "step " << k << ": " << v.violations.front().describe();

    // The contract for this step. Vertices of the previous world more than 3 units from the
    // tool's box lie on the boundary of their unchanged exact pieces: only the others are
    // measured (the cost of the vertex check then stays proportional to the change).
    const ExactRegion tool_exact = oracle(k, "tool", [&] { return ExactRegion::of(tool); });
    const ExactCase step = oracle(
        k, "exact_clip", [&] { return exact_clip(op, world, tools, world_exact, tool_exact); });
    Box64 near = *bounding_box(tool);
    near.min = {near.min.x - 3, near.min.y - 3};
    near.max = {near.max.x + 3, near.max.y + 3};
    std::unordered_set<Point64, Point64Hash> old_vertices;
    for (const Polygon& p : world) old_vertices.insert(p.begin(), p.end());
    options.skip_vertex = [&](Point64 vertex) {
      return old_vertices.contains(vertex) && !near.contains(vertex);
    };
    std::vector<Point64> inputs(tool.begin(), tool.end());
    options.seed = k;
    const ContractReport rep = oracle(k, "check_contract", [&] {
      return check_contract(step, *o.result, inputs,
                            "step " + std::to_string(k) + ": " + describe_case(op, world, tools),
                            options);
    });
    ASSERT_TRUE(rep.ok()) << rep.failure;

    const ExactRegion next_exact =
        oracle(k, "region of the output", [&] { return ExactRegion::of(next); });
    const Rational step_error = oracle(
        k, "output xor exact", [&] { return next_exact.apply(ClipOp::kXor, step.result).area(); });
    const Rational step_band =
        oracle(k, "local band", [&] { return local_band(step.result, tool); });
    ASSERT_LE(step_error, step_band)
        << "step " << k << ": output xor exact exceeds the local band\n  "
        << describe_case(op, world, tools) << "\n  output = " << to_wkt(next);
    measured += step_error;
    accumulated += step_band;
    chain = oracle(k, "exact chain", [&] { return chain.apply(op, tool_exact); });
    const Rational drift = abs(Rational(area(next) - chain.area()));
    ASSERT_LE(drift, accumulated) << "step " << k << ": area drifted from the exact chain";

    if (o.result->stats.vertices_snapped) ++snapped_steps;
    holes += o.result->stats.holes_split;
    world = next;
    world_exact = next_exact;
    max_vertices = std::max(max_vertices, vertex_count(world));
    if (k % 500 == 0)  // progress of long runs (EDGELAND_CHAIN_STEPS in the thousands)
      std::cout << "[chain] step " << k << ": " << world.size() << " polygons / "
                << vertex_count(world) << " vertices, drift "
                << abs(Rational(area(world) - chain.area())).convert_to<double>() << std::endl;
  }
  const Rational final_sym =
      oracle(steps, "final xor", [&] { return world_exact.apply(ClipOp::kXor, chain).area(); });
  EXPECT_LE(final_sym, measured) << "triangle inequality of the exact reference itself";
  const OracleFallbacks fallbacks = fallbacks_since(fallbacks_before);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "[chain] seed " << seed << ": " << steps << " steps in " << secs << " s, "
            << snapped_steps << " steps snapped, " << holes << " holes split, final "
            << world.size() << " polygons / " << vertex_count(world) << " vertices (max "
            << max_vertices << "), |area - exact chain| = "
            << abs(Rational(area(world) - chain.area())).convert_to<double>()
            << ", area(world xor exact chain) = " << final_sym.convert_to<double>()
            << ", accumulated bound = " << accumulated.convert_to<double>()
            << "; oracle fallbacks (CGAL failures got past): " << fallbacks.rebuilt << " rebuilt, "
            << fallbacks.split << " split, " << fallbacks.part_by_part << " part by part, "
            << fallbacks.members_in_halves << " members in halves\n";
}

}  // namespace
}  // namespace edgeland::test
