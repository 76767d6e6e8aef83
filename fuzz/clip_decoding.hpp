#pragma once
// How the clipper's targets (clip_pair, clip_sequence, normalize) decode operands from fuzz
// input: one point palette shared by both operands and the steps of a sequence, so a saved
// input means the same shapes in each target. Defined in clip_decoding.cpp.
#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"

namespace edgeland::fuzz {

using Provider = FuzzedDataProvider;

inline constexpr std::size_t kMaxPalette = 24;
inline constexpr std::size_t kMaxShapes = 6;
inline constexpr std::size_t kMaxSetVertices = 64;  // per decoded operand
// Coordinates within this bound make an input "small": the exact references then run.
inline constexpr std::int64_t kSmallBound = std::int64_t{1} << 20;

inline constexpr std::array<ClipOp, 4> kOps{ClipOp::kUnion, ClipOp::kIntersection,
                                            ClipOp::kDifference, ClipOp::kXor};
inline constexpr std::array<FillRule, 4> kRules{FillRule::kEvenOdd, FillRule::kNonZero,
                                                FillRule::kPositive, FillRule::kNegative};

// Text for findings and logs, built only when something is found: on the small inputs fuzzing
// feeds, writing WKT for every operation cost as much as the operations (issue 18).
using Text = std::function<std::string()>;

// "op\n  A = ...\n  B = ...": an operation and its operands, for findings.
std::string op_line(ClipOp op, const PolygonSet& a, const PolygonSet& b);
// The operation as a continuous-clip log (a set line and a step line).
std::string pair_log(ClipOp op, const PolygonSet& a, const PolygonSet& b);
std::size_t vertex_count(const PolygonSet& set);

// Structure-aware decoding. Every point is drawn from a shared palette, so the two operands
// (and the steps of a sequence) reuse each other's vertices, lie on each other's edges and pass
// through the same pixels: the near-degenerate cases the clipper must survive.
class Decoder {
 public:
  explicit Decoder(Provider& in);

  // Adds a few vertices of `set` to the palette (continuous clipping: the next edit touches
  // what the previous ones made).
  void absorb(const PolygonSet& set);
  // A valid set: the decoded shapes as they are when they already form a valid set (members
  // may then share edges), else normalized with a decoded fill rule.
  PolygonSet valid_set();
  // Arbitrary rings for normalize (and invalid operands): palette points, repeats, and with
  // `out_of_range`, now and then a raw 64-bit coordinate.
  std::vector<Ring> raw_rings(bool out_of_range);

 private:
  void pick_window();
  std::int64_t coord();
  Point64 fresh();
  Point64 pick();
  void remember(Point64 p);
  Point64 unit_offset();
  Point64 on_segment(Point64 a, Point64 b);
  std::int64_t extreme_coord();
  void add_point();
  std::vector<Ring> shape();
  Ring fan();
  std::vector<Ring> strips();

  Provider& in_;
  std::int64_t lo_ = 0, hi_ = 0;
  std::vector<Point64> palette_;
};

}  // namespace edgeland::fuzz
