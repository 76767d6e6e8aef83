// edgeland itself, twice:
//  * "edgeland": PolygonSet in, PolygonSet out, both operands validated on every operation
//    (what clip(op, PolygonSet, PolygonSet) does), the whole pipeline timed;
//  * "edgeland_valid": ValidSet in, ValidSet out (clip.hpp): operands are validated once when
//    loaded (not timed, like every peer's conversion), and a result is the next subject
//    without re-validation, as a game carving one set keeps it.
#include <utility>

#include "peer.hpp"

namespace edgeland::bench {
namespace {

PolygonSet clip_sets(ClipOp op, const PolygonSet& a, const PolygonSet& b, ClipStats& stats) {
  ClipResult r = clip(op, a, b);
  stats = r.stats;
  return std::move(r.polygons);
}

ValidSet clip_sets(ClipOp op, const ValidSet& a, const ValidSet& b, ClipStats& stats) {
  ValidClipResult r = clip(op, a, b);
  stats = r.stats;
  return std::move(r.set);
}

const PolygonSet& polygons_of(const PolygonSet& s) { return s; }
const PolygonSet& polygons_of(const ValidSet& s) { return s.polygons(); }

template <class Set>
struct EdgelandShape final : Shape {
  Set set;
  ClipStats stats;
};

template <class Set>
class EdgelandPeer final : public Peer {
  using Own = EdgelandShape<Set>;

 public:
  explicit EdgelandPeer(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    auto shape = std::make_unique<Own>();
    shape->set = Set(set);
    return shape;
  }
  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    auto out = std::make_unique<Own>();
    out->set = clip_sets(op, static_cast<const Own&>(subject).set,
                         static_cast<const Own&>(clip_shape).set, out->stats);
    return out;
  }
  std::size_t vertex_count(const Shape& shape) const override {
    std::size_t n = 0;
    for (const Polygon& p : polygons_of(static_cast<const Own&>(shape).set)) n += p.size();
    return n;
  }
  PeerRings rings(const Shape& shape) const override {
    return {polygons_of(static_cast<const Own&>(shape).set), {}};
  }
  std::size_t intersections(const Shape& result) const override {
    return static_cast<const Own&>(result).stats.intersections;
  }

 private:
  std::string name_;
};

}  // namespace

std::unique_ptr<Peer> make_edgeland_peer() {
  return std::make_unique<EdgelandPeer<PolygonSet>>("edgeland");
}

std::unique_ptr<Peer> make_edgeland_valid_peer() {
  return std::make_unique<EdgelandPeer<ValidSet>>("edgeland_valid");
}

}  // namespace edgeland::bench
