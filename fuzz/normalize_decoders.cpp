// The `normalize` target (decoders.hpp): arbitrary rings through normalize() under a decoded
// fill rule and, read as one OGC polygon, through import_polygons(); winding numbers far from
// every ring as the reference.
#include <exception>

#include "clip_decoding.hpp"
#include "clip_references.hpp"
#include "decoders.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

// Runs `fill` (normalize or import_polygons of rings, checked mode) into `result`. A finding
// (wrapped) when it fails other than by the documented typed error for out-of-range rings,
// accepts such rings, or returns an invalid set; nullopt (unwrapped) when all is well, and a
// wrapped nullopt when the typed error was rightly thrown (nothing more to check).
template <class Fill>
std::optional<std::optional<Finding>> filled_checks(const Text& context, bool out_of_range,
                                                    ClipResult& result, Fill&& fill) {
  try {
    result = fill();
  } catch (const InternalError& e) {
    return Finding{std::string("InternalError: ") + e.what() + "\n  " + context(), ""};
  } catch (const InvalidInput& e) {
    if (out_of_range) return std::optional<Finding>{};  // the documented typed error
    return Finding{std::string("in-range rings rejected: ") + e.what() + "\n  " + context(), ""};
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what() + "\n  " + context(), ""};
  }
  if (out_of_range) return Finding{"out-of-range coordinate accepted: " + context(), ""};
  if (auto f = invalid_output(context, result.polygons, [] { return std::string(); })) return f;
  return std::nullopt;
}

// The same rings read as one OGC polygon (ring 0 its exterior, the rest its holes) by
// import_polygons: valid output, and far from every ring a point is inside exactly when the
// rings winding around it (exterior +1, holes -1) sum to more than zero (clip.hpp).
std::optional<Finding> import_checks(const std::vector<Ring>& rings, bool out_of_range) {
  if (rings.empty()) return std::nullopt;
  const std::vector<std::vector<Ring>> polygons{rings};
  const Text context = [&] {
    return "import_polygons of the polygon " + to_wkt(PolygonSet(rings.begin(), rings.end())) +
           " (ring 0 its exterior)";
  };
  ClipResult result;
  if (auto f = filled_checks(context, out_of_range, result, [&] {
        return import_polygons(polygons, ClipOptions{.checked = true});
      }))
    return *f;
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    int value = 0;
    for (std::size_t r = 0; r < rings.size(); ++r)
      value += (winding_number(q, rings[r]) != 0 ? 1 : 0) * (r == 0 ? 1 : -1);
    const bool actual = locate(q, result.polygons) != PointLocation::kOutside;
    if ((value > 0) != actual)
      return Finding{"point " + point_text(q) + (actual ? " is" : " is not") +
                         " in the output of " + context() +
                         "\n  output = " + to_wkt(result.polygons),
                     ""};
  }
  return std::nullopt;
}

std::optional<Finding> normalize_checks(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  Decoder decoder(in);
  const FillRule rule = in.PickValueInArray(kRules);
  const std::vector<Ring> rings = decoder.raw_rings(true);
  bool out_of_range = false;
  for (const Ring& r : rings) {
    for (const Point64& p : r) out_of_range = out_of_range || !in_range(p);
  }
  const Text context = [&] {
    return std::string("normalize ") + fill_rule_name(rule) +
           " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end()));
  };
  ClipResult result;
  if (auto f = filled_checks(context, out_of_range, result,
                             [&] { return normalize(rings, rule, ClipOptions{.checked = true}); }))
    return *f;
  if (auto f = import_checks(rings, out_of_range)) return f;
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    int w = 0;
    for (const Ring& r : rings) w += winding_number(q, r);
    const bool expected = rule_fills(rule, w);
    const bool actual = locate(q, result.polygons) != PointLocation::kOutside;
    if (expected != actual) {
      return Finding{"point " + point_text(q) + " with winding number " + std::to_string(w) +
                         (actual ? " is" : " is not") + " in the output of " + context() +
                         "\n  output = " + to_wkt(result.polygons),
                     ""};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_normalize(const std::uint8_t* data, std::size_t size) {
  try {
    return normalize_checks(data, size);
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what(), ""};
  }
}

}  // namespace edgeland::fuzz
