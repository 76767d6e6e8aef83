// The `clip_pair` target (decoders.hpp): two valid sets from one palette, all four operations,
// area identities and point classification against exact references.
#include <array>
#include <exception>

#include "clip_decoding.hpp"
#include "clip_references.hpp"
#include "decoders.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/perimeter.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

struct Pair {
  PolygonSet a, b;
};

Pair decode_pair(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  Decoder decoder(in);
  Pair pair;
  pair.a = decoder.valid_set();
  pair.b = decoder.valid_set();
  return pair;
}

std::optional<Finding> check_pair_areas(const Pair& p, const std::array<ClipResult, 4>& r) {
  const Int128 a = twice_signed_area(p.a), b = twice_signed_area(p.b);
  const Int128 u = twice_signed_area(r[0].polygons), i = twice_signed_area(r[1].polygons);
  const Int128 d = twice_signed_area(r[2].polygons), x = twice_signed_area(r[3].polygons);
  bool exact = true;
  for (const ClipResult& res : r) exact = exact && res.stats.vertices_snapped == 0;
  // Accuracy contract: |area(out) - area(R)| <= perimeter(R) <= perimeter(A) + perimeter(B),
  // so each identity below is off by at most that per result involved (twice-area units: 2x).
  const Int128 p_ab = perimeter_bounds(p.a).hi + perimeter_bounds(p.b).hi;
  struct Identity {
    const char* name;
    Int128 error;
    Int128 bound;
  };
  const std::array<Identity, 3> identities{{
      {"|A n B| + |A - B| = |A|", i + d - a, 4 * p_ab},
      {"|A u B| = |A| + |B| - |A n B|", u - (a + b - i), 4 * p_ab},
      {"|A x B| = |A u B| - |A n B|", x - (u - i), 6 * p_ab},
  }};
  for (const Identity& id : identities) {
    const Int128 err = id.error < 0 ? -id.error : id.error;
    if ((exact && err != 0) || err > id.bound) {
      return Finding{
          std::string("area identity ") + id.name + (exact ? " (exact: nothing snapped)" : "") +
              " off by " + to_string(err) + "/2 (bound " + to_string(id.bound) +
              "/2)\n  A = " + to_wkt(p.a) + "\n  B = " + to_wkt(p.b),
          pair_log(ClipOp::kIntersection, p.a, p.b) + pair_log(ClipOp::kDifference, p.a, p.b)};
    }
  }
  return std::nullopt;
}

std::optional<Finding> check_pair_points(const Pair& p, const std::array<ClipResult, 4>& r) {
  std::vector<Ring> rings(p.a.begin(), p.a.end());
  rings.insert(rings.end(), p.b.begin(), p.b.end());
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    const bool in_a = locate(q, p.a) == PointLocation::kInside;
    const bool in_b = locate(q, p.b) == PointLocation::kInside;
    for (std::size_t k = 0; k < kOps.size(); ++k) {
      const bool expected = op_keeps(kOps[k], in_a, in_b);
      const bool actual = locate(q, r[k].polygons) != PointLocation::kOutside;
      if (expected != actual) {
        return Finding{std::string("point ") + point_text(q) +
                           " farther than 1.5 from both boundaries is " +
                           (actual ? "in" : "not in") + " the output but " +
                           (expected ? "in" : "not in") + " the exact result of " +
                           op_line(kOps[k], p.a, p.b) + "\n  output = " + to_wkt(r[k].polygons),
                       pair_log(kOps[k], p.a, p.b)};
      }
    }
  }
  return std::nullopt;
}

std::optional<Finding> clip_pair_checks(const Pair& p) {
  std::array<ClipResult, 4> results;
  for (std::size_t k = 0; k < kOps.size(); ++k) {
    const Text log_text = [&] { return pair_log(kOps[k], p.a, p.b); };
    const Text line = [&] { return op_line(kOps[k], p.a, p.b); };
    try {
      results[k] = clip(kOps[k], p.a, p.b, ClipOptions{.checked = true});
    } catch (const InternalError& e) {
      return Finding{std::string("InternalError: ") + e.what() + "\n  " + line(), log_text()};
    } catch (const std::exception& e) {
      return Finding{
          std::string("unexpected exception on valid inputs: ") + e.what() + "\n  " + line(),
          log_text()};
    }
    if (auto f = invalid_output(line, results[k].polygons, log_text)) return f;
  }
  if (auto f = check_pair_areas(p, results)) return f;
  return check_pair_points(p, results);
}

// The validating clip() (PolygonSet operands, which may be invalid here): InvalidInput exactly

}  // namespace

std::optional<Finding> run_clip_pair(const std::uint8_t* data, std::size_t size) {
  Pair pair;
  try {
    pair = decode_pair(data, size);
  } catch (const std::exception& e) {  // decoding normalizes: a failure there is a finding too
    return Finding{std::string("decoding (normalize) failed: ") + e.what(), ""};
  }
  return clip_pair_checks(pair);
}

std::string clip_pair_log(const std::uint8_t* data, std::size_t size) {
  const Pair pair = decode_pair(data, size);
  std::string text;
  for (const ClipOp op : kOps) text += pair_log(op, pair.a, pair.b);
  return text;
}

}  // namespace edgeland::fuzz
