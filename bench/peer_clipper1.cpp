// Clipper 1 (libpolyclipping 6.4.2): integer coordinates, Paths in and out, non-zero fill.
// Outer rings come out with positive area and holes with negative area, so a result is
// directly a valid non-zero subject for the next operation.
#include <clipper.hpp>

#include "peer.hpp"
#include "peer_conversion.hpp"

namespace edgeland::bench {
namespace {

struct ClipperShape final : Shape {
  ClipperLib::Paths paths;
};

ClipperLib::ClipType clip_type(ClipOp op) {
  switch (op) {
    case ClipOp::kUnion:
      return ClipperLib::ctUnion;
    case ClipOp::kIntersection:
      return ClipperLib::ctIntersection;
    case ClipOp::kDifference:
      return ClipperLib::ctDifference;
    case ClipOp::kXor:
      return ClipperLib::ctXor;
  }
  return ClipperLib::ctUnion;
}

class ClipperPeer final : public Peer {
 public:
  std::string name() const override { return "clipper1"; }
  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    auto shape = std::make_unique<ClipperShape>();
    for (const Polygon& polygon : set) {
      ClipperLib::Path path;
      path.reserve(polygon.size());
      for (const Point64& p : polygon) path.emplace_back(p.x, p.y);
      shape->paths.push_back(std::move(path));
    }
    return shape;
  }
  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(static_cast<const ClipperShape&>(subject).paths, ClipperLib::ptSubject, true);
    clipper.AddPaths(static_cast<const ClipperShape&>(clip_shape).paths, ClipperLib::ptClip, true);
    auto out = std::make_unique<ClipperShape>();
    clipper.Execute(clip_type(op), out->paths, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
  }
  std::size_t vertex_count(const Shape& shape) const override {
    std::size_t n = 0;
    for (const auto& path : static_cast<const ClipperShape&>(shape).paths) n += path.size();
    return n;
  }
  PeerRings rings(const Shape& shape) const override {
    PeerRings out;
    for (const auto& path : static_cast<const ClipperShape&>(shape).paths) {
      Ring ring;
      ring.reserve(path.size());
      for (const auto& p : path) ring.push_back({p.X, p.Y});
      // Clipper marks holes by orientation only.
      (ClipperLib::Orientation(path) ? out.outers : out.holes).push_back(as_open_ccw(ring));
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<Peer> make_clipper1_peer() { return std::make_unique<ClipperPeer>(); }

}  // namespace edgeland::bench
