#pragma once
// How the landscape targets (edit_sequence, game_sequence) decode a world and its edits from
// fuzz input: one decoding for both, so a shape means the same in each. Defined in
// landscape_decoders.cpp.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <string>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::fuzz {

using Provider = FuzzedDataProvider;

inline constexpr int kMaxEdits = 24;
inline constexpr std::size_t kMaxShapePoints = 24;
// Small enough that a run stays fast; an edit that would pass it is a typed LimitExceeded.
inline constexpr LandscapeLimits kLimits{.max_vertices = 6000, .max_shape_vertices = 200};

// The world, its configuration, and shapes whose points come from the places that matter: the
// cell lines of the world's first levels, the vertices already in the landscape, one-unit
// offsets from those, and (rarely) coordinates past the bound.
class EditDecoder {
 public:
  explicit EditDecoder(Provider& in) : in_(in) {}

  Box64 world();
  LandscapeConfig config();
  // A point near the world: a cell line, a landscape vertex, or anywhere, nudged by a unit.
  Point64 point(const Landscape& l);
  // A shape: a rectangle, a triangle, or a ring of up to kMaxShapePoints points (which may
  // cross itself: then the edit must fail with InvalidInput and change nothing), sometimes with
  // a coordinate past the bound (CoordinateOutOfRange); or one of kernel/shapes.hpp's builders
  // (circle, regular polygon, capsule, rotated box) with radii from 1 to 2^33 around points near
  // the world, now and then an argument out of its range.
  PolygonSet shape(const Landscape& l);
  // What a shape builder did against its contract in the last shape() (empty: nothing): a
  // polygon that is not valid, strictly convex and in range, a typed error for arguments in
  // their ranges, or no error for one out of its range.
  const std::string& builder_problem() const { return builder_problem_; }
  // A material map over materials 0..4 (relabel edits).
  MaterialMap material_map();

 private:
  Polygon shape_rectangle(const Landscape& l);
  Polygon built_shape(const Landscape& l);
  std::int64_t shape_radius(bool& in_range);
  Point64 shape_center(const Landscape& l, bool& in_range);
  Point64 anywhere();
  Point64 cell_line_point();
  Point64 landscape_vertex(const Landscape& l);

  Provider& in_;
  Box64 world_;
  std::string builder_problem_;
};

// One edit as decoded: what to do, with which materials and shape, and whether to take a
// snapshot of the landscape before it.
struct DecodedEdit {
  int kind;  // 0 carve, 1 fill, 2 fill_empty, 3 replace, 4 relabel
  Material a, b;
  MaterialMap map;  // relabel's
  PolygonSet shape;
  bool snapshot;
  std::string builder_problem;  // EditDecoder::builder_problem() of its shape
};

DecodedEdit next_edit(Provider& in, EditDecoder& decode, const Landscape& l);
// The world and configuration an input starts with (materials 0..4 appear in it).
Landscape decode_world(Provider& in, EditDecoder& decode);
// Applies the edit (throws what the landscape's edits throw).
ChangeSet apply(Landscape& l, const DecodedEdit& d);
// The edit as a landscape log line.
std::string edit_text(const DecodedEdit& d);

}  // namespace edgeland::fuzz
