// The accuracy contract as an oracle (see accuracy_contract.hpp for the checks).
#include "accuracy_contract.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

QPoint to_q(const SamplePoint& p) { return {Rational(p.x) / p.den, Rational(p.y) / p.den}; }

std::string show(const SamplePoint& p) {
  std::ostringstream os;
  os << '(' << to_q(p).x.str() << ' ' << to_q(p).y.str() << ')';
  return os.str();
}

// The sample points of accuracy_contract.hpp, deterministic for a given seed.
std::vector<SamplePoint> sample_points(const std::vector<Point64>& inputs, const PolygonSet& output,
                                       const ContractOptions& o) {
  std::optional<Box64> box;
  auto add = [&](Point64 p) {
    if (box)
      box->expand(p);
    else
      box = Box64{p, p};
  };
  for (const Point64& p : inputs) add(p);
  for (const Polygon& poly : output)
    for (const Point64& p : poly) add(p);
  std::vector<SamplePoint> pts;
  if (!box) return pts;
  // Two units of margin, clamped so that scaled coordinates stay small.
  const std::int64_t lim = kCoordBound + 2;
  const std::int64_t x0 = std::max(box->min.x - 2, -lim), x1 = std::min(box->max.x + 2, lim);
  const std::int64_t y0 = std::max(box->min.y - 2, -lim), y1 = std::min(box->max.y + 2, lim);
  const Int128 nx = Int128(x1 - x0) * 2 + 1, ny = Int128(y1 - y0) * 2 + 1;
  if (nx * ny <= Int128(o.dense_grid_limit)) {
    for (std::int64_t x = 2 * x0; x <= 2 * x1; ++x)
      for (std::int64_t y = 2 * y0; y <= 2 * y1; ++y) pts.push_back({x, y, 2});
    return pts;
  }
  std::mt19937_64 rng(o.seed);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  for (std::size_t i = 0; i < o.random_points; ++i)
    pts.push_back({uniform(4 * x0, 4 * x1), uniform(4 * y0, 4 * y1), 4});
  std::vector<Point64> near = inputs;
  std::shuffle(near.begin(), near.end(), rng);
  if (near.size() > 200) near.resize(200);
  for (const Point64& v : near)
    for (std::size_t k = 0; k < o.points_per_vertex; ++k)
      pts.push_back({4 * v.x + uniform(-12, 12), 4 * v.y + uniform(-12, 12), 4});
  return pts;
}

std::string where_text(Where w) {
  return w == Where::kInside ? "inside" : w == Where::kOutside ? "outside" : "on the boundary";
}

}  // namespace

std::string describe_case(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  return std::string(op_name(op)) + "\n  A = " + to_wkt(a) + "\n  B = " + to_wkt(b);
}

ExactCase exact_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  return exact_clip(op, a, b, ExactRegion::of(a), ExactRegion::of(b));
}

ExactCase exact_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b, const ExactRegion& ra,
                     const ExactRegion& rb) {
  // Shared lazily computed pieces, per member of each operand.
  struct Pieces {
    ClipOp op;
    PolygonSet a, b;
    ExactRegion ra, rb;
    std::vector<std::optional<ExactRegion>> of_a, of_b;
    bool near(Point64 v, const PolygonSet& set, std::vector<std::optional<ExactRegion>>& cache,
              bool subject) {
      for (std::size_t i = 0; i < set.size(); ++i) {
        Box64 box = *bounding_box(set[i]);
        box.min = {box.min.x - 1, box.min.y - 1};
        box.max = {box.max.x + 1, box.max.y + 1};
        if (!box.contains(v)) continue;
        if (!cache[i]) {
          const ExactRegion member = ExactRegion::of(set[i]);
          if (!subject)
            cache[i] = member.apply(ClipOp::kDifference, ra);
          else if (op == ClipOp::kUnion)
            cache[i] = member;
          else if (op == ClipOp::kIntersection)
            cache[i] = member.apply(ClipOp::kIntersection, rb);
          else
            cache[i] = member.apply(ClipOp::kDifference, rb);
        }
        if (cache[i]->boundary_within(to_q(v), 1)) return true;
      }
      return false;
    }
  };
  auto shared = std::make_shared<Pieces>(Pieces{op, a, b, ra, rb,
                                                std::vector<std::optional<ExactRegion>>(a.size()),
                                                std::vector<std::optional<ExactRegion>>(b.size())});
  ExactCase c;
  c.result = shared->ra.apply(op, shared->rb);
  c.near_piece_boundary = [shared](Point64 v) {
    if (shared->near(v, shared->a, shared->of_a, true)) return true;
    const bool clip_pieces = shared->op == ClipOp::kUnion || shared->op == ClipOp::kXor;
    return clip_pieces && shared->near(v, shared->b, shared->of_b, false);
  };
  return c;
}

ExactCase exact_clip_to_box(const PolygonSet& set, const Box64& box) {
  const Polygon cell{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  return exact_clip(ClipOp::kIntersection, set, PolygonSet{cell});
}

ExactCase exact_region(const ExactRegion& region) {
  return {region, [region](Point64 v) { return region.boundary_within(to_q(v), 1); }};
}

ContractReport check_contract(const ExactCase& exact, const ClipResult& out,
                              const std::vector<Point64>& inputs, const std::string& context,
                              const ContractOptions& options) {
  ContractReport report;
  const PolygonSet& s = out.polygons;
  const ExactRegion& r = exact.result;
  auto fail = [&](const std::string& what) {
    report.failure = what + "\n  " + context + "\n  output = " + to_wkt(s) +
                     "\n  exact  = " + r.to_text() +
                     "\n  vertices_snapped = " + std::to_string(out.stats.vertices_snapped);
    return report;
  };
  const bool snapped = out.stats.vertices_snapped != 0;

  // 1. Validity.
  const ValidationReport valid = validate(s);
  if (!valid.ok()) return fail("invalid output: " + valid.violations.front().describe());

  // 2. Area.
  const Rational area_s = Rational(BigInt(to_string(twice_area(s)))) / 2;
  const Rational area_r = r.area();
  const Rational error = abs(Rational(area_s - area_r));
  if (!snapped && error != 0)
    return fail("area " + area_s.str() + " differs from the exact " + area_r.str() +
                " although nothing was snapped");
  const BigInt perimeter = r.perimeter_ceil();
  if (error > Rational(perimeter))
    return fail("area error " + error.str() + " exceeds the perimeter bound " + perimeter.str());

  // 3. Vertices within one unit of the boundary of the exact pieces.
  for (const Polygon& poly : s)
    for (const Point64& v : poly) {
      if (options.skip_vertex && options.skip_vertex(v)) continue;
      if (r.boundary_within(to_q(v), 1) || exact.near_piece_boundary(v)) continue;
      return fail("output vertex (" + std::to_string(v.x) + ' ' + std::to_string(v.y) +
                  ") is farther than 1 from the exact boundary");
    }

  // 4. Classification of sample points.
  const Rational far = Rational(9) / 4;
  for (const SamplePoint& p : sample_points(inputs, s, options)) {
    const QPoint qp = to_q(p);
    const Where ws = locate(s, p);
    if (!snapped) {
      const ExactRegion::Location lr = r.locate(qp);
      const bool in_r = lr != ExactRegion::Location::kOutside;
      const bool in_s = ws != Where::kOutside;
      ++report.points_tested;
      if (in_r != in_s)
        return fail("unsnapped output: point " + show(p) + " is " + where_text(ws) +
                    " of the output but " + (in_r ? "in" : "not in") + " the exact closure");
      continue;
    }
    if (r.boundary_within(qp, far)) continue;
    ++report.points_tested;
    // The closure of S: a point on an edge shared by two output pieces (internal boundary)
    // is inside. A point on the outer boundary of S this far from the boundary of R fails
    // unless it is inside R, where it can only be on an internal edge.
    const bool in_r = r.locate(qp) == ExactRegion::Location::kInside;
    if (in_r != (ws != Where::kOutside))
      return fail("point " + show(p) + " farther than 1.5 from the exact boundary is " +
                  where_text(ws) + " of the output but " + (in_r ? "inside" : "outside") +
                  " the exact result");
  }

  // 5. Symmetric difference within the 1.5-band around the exact boundary.
  if (options.symmetric_difference_bound) {
    const Rational sym = ExactRegion::of(s).apply(ClipOp::kXor, r).area();
    const Rational band =
        Rational(3) * Rational(perimeter) + Rational(9 * 22, 4 * 7) * Rational(r.boundary_cycles());
    if (sym > band)
      return fail("area of output xor exact " + sym.str() + " exceeds the 1.5-band bound " +
                  band.str());
  }
  return report;
}

ContractReport check_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b,
                          const ClipResult& out, const ContractOptions& options) {
  std::vector<Point64> inputs;
  for (const PolygonSet* set : {&a, &b})
    for (const Polygon& p : *set) inputs.insert(inputs.end(), p.begin(), p.end());
  return check_contract(exact_clip(op, a, b), out, inputs, describe_case(op, a, b), options);
}

}  // namespace edgeland::test
