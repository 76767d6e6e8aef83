#pragma once
// Runs the clipper in checked mode for the tests, turning every exception into a failure
// message that carries the inputs (so a property failure always names its case as WKT).
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::test {

// Either the result or the message of the exception thrown.
struct Outcome {
  std::optional<ClipResult> result;
  std::string error;
  bool ok() const { return result.has_value(); }
};

inline Outcome run_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  Outcome o;
  try {
    o.result = clip(op, a, b, ClipOptions{.checked = true});
  } catch (const InternalError& e) {
    o.error = std::string("InternalError: ") + e.what() + "\n  subject = " + e.subject_wkt +
              "\n  clip = " + e.clip_wkt;
  } catch (const std::exception& e) {
    o.error = std::string("exception: ") + e.what() + "\n  " + op_name(op) +
              "\n  A = " + to_wkt(a) + "\n  B = " + to_wkt(b);
  }
  return o;
}

inline Outcome run_normalize(const std::vector<Ring>& rings, FillRule rule) {
  Outcome o;
  try {
    o.result = normalize(rings, rule, ClipOptions{.checked = true});
  } catch (const std::exception& e) {
    o.error = std::string("exception: ") + e.what() + "\n  normalize " + fill_rule_name(rule) +
              " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end()));
  }
  return o;
}

inline Outcome run_import(const std::vector<std::vector<Ring>>& polygons) {
  Outcome o;
  try {
    o.result = import_polygons(polygons, ClipOptions{.checked = true});
  } catch (const std::exception& e) {
    PolygonSet rings;
    for (const auto& polygon : polygons) rings.insert(rings.end(), polygon.begin(), polygon.end());
    o.error =
        std::string("exception: ") + e.what() + "\n  import_polygons rings = " + to_wkt(rings);
  }
  return o;
}

inline Outcome run_clip_to_box(const PolygonSet& a, const Box64& box) {
  Outcome o;
  try {
    o.result = clip_to_box(a, box, ClipOptions{.checked = true});
  } catch (const std::exception& e) {
    o.error = std::string("exception: ") + e.what() + "\n  clip_to_box A = " + to_wkt(a);
  }
  return o;
}

}  // namespace edgeland::test
