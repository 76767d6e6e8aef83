// The exact references of the clipper's targets (clip_references.hpp).
#include "clip_references.hpp"

#include <algorithm>

#include "edgeland/kernel/canonical_form.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

// Whether p is farther than 1.5 units from segment a-b: 4 dist^2 > 9, exactly. Needs
// coordinates within kSmallBound (squared cross products fit in 128 bits).
bool far_from_segment(Point64 p, Point64 a, Point64 b) {
  const Int128 abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
  const Int128 len2 = abx * abx + aby * aby;
  const Int128 t = apx * abx + apy * aby;
  if (len2 == 0 || t <= 0) return 4 * (apx * apx + apy * apy) > 9;
  if (t >= len2) {
    const Int128 bpx = p.x - b.x, bpy = p.y - b.y;
    return 4 * (bpx * bpx + bpy * bpy) > 9;
  }
  const Int128 cross = abx * apy - aby * apx;
  return 4 * cross * cross > 9 * len2;
}

}  // namespace

bool small(const std::vector<Ring>& rings) {
  for (const Ring& r : rings) {
    for (const Point64& p : r) {
      if (p.x < -kSmallBound || p.x > kSmallBound || p.y < -kSmallBound || p.y > kSmallBound) {
        return false;
      }
    }
  }
  return true;
}

bool far_from_rings(Point64 p, const std::vector<Ring>& rings) {
  for (const Ring& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!far_from_segment(p, r[i], r[(i + 1) % r.size()])) return false;
    }
  }
  return true;
}

std::vector<Point64> sample_points(const std::vector<Ring>& rings) {
  std::vector<Point64> points;
  std::int64_t x0 = kSmallBound, y0 = kSmallBound, x1 = -kSmallBound, y1 = -kSmallBound;
  for (const Ring& r : rings) {
    for (const Point64& p : r) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
      for (const Point64 d : {Point64{2, 0}, Point64{-2, 0}, Point64{0, 2}, Point64{0, -2},
                              Point64{2, 2}, Point64{-2, -2}, Point64{2, -2}, Point64{-2, 2}}) {
        points.push_back({p.x + d.x, p.y + d.y});
      }
    }
  }
  if (x0 > x1) return points;
  x0 -= 3, y0 -= 3, x1 += 3, y1 += 3;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      points.push_back({x0 + (x1 - x0) * i / 8, y0 + (y1 - y0) * j / 8});
    }
  }
  return points;
}

bool op_keeps(ClipOp op, bool in_a, bool in_b) {
  switch (op) {
    case ClipOp::kUnion:
      return in_a || in_b;
    case ClipOp::kIntersection:
      return in_a && in_b;
    case ClipOp::kDifference:
      return in_a && !in_b;
    case ClipOp::kXor:
      break;
  }
  return in_a != in_b;
}

bool rule_fills(FillRule rule, int w) {
  switch (rule) {
    case FillRule::kEvenOdd:
      return (w % 2) != 0;
    case FillRule::kNonZero:
      return w != 0;
    case FillRule::kPositive:
      return w > 0;
    case FillRule::kNegative:
      break;
  }
  return w < 0;
}

std::string point_text(Point64 p) {
  return "(" + std::to_string(p.x) + " " + std::to_string(p.y) + ")";
}

std::optional<Finding> invalid_output(const Text& context, const PolygonSet& out,
                                      const Text& log_text) {
  const ValidationReport report = validate(out, 1);
  std::string problem;
  if (!report.ok()) {
    problem = "invalid: " + report.violations.front().describe();
  } else if (const auto order = canonical_violation(out)) {
    problem = "not canonical: " + order->describe();
  }
  if (problem.empty()) return std::nullopt;
  return Finding{"output (" + problem + ") of " + context() + "\n  output = " + to_wkt(out),
                 log_text()};
}

}  // namespace edgeland::fuzz
