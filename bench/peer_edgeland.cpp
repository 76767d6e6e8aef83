// edgeland itself: PolygonSet in, PolygonSet out, the whole pipeline timed.
#include <utility>

#include "peer.hpp"

namespace edgeland::bench {
namespace {

struct EdgelandShape final : Shape {
  PolygonSet set;
  ClipStats stats;
};

class EdgelandPeer final : public Peer {
 public:
  std::string name() const override { return "edgeland"; }
  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    auto shape = std::make_unique<EdgelandShape>();
    shape->set = set;
    return shape;
  }
  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    auto out = std::make_unique<EdgelandShape>();
    ClipResult result = clip(op, static_cast<const EdgelandShape&>(subject).set,
                             static_cast<const EdgelandShape&>(clip_shape).set);
    out->set = std::move(result.polygons);
    out->stats = result.stats;
    return out;
  }
  std::size_t vertex_count(const Shape& shape) const override {
    std::size_t n = 0;
    for (const Polygon& p : static_cast<const EdgelandShape&>(shape).set) n += p.size();
    return n;
  }
  PeerRings rings(const Shape& shape) const override {
    return {static_cast<const EdgelandShape&>(shape).set, {}};
  }
  std::size_t intersections(const Shape& result) const override {
    return static_cast<const EdgelandShape&>(result).stats.intersections;
  }
};

}  // namespace

std::unique_ptr<Peer> make_edgeland_peer() { return std::make_unique<EdgelandPeer>(); }

}  // namespace edgeland::bench
