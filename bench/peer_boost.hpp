#pragma once
// Boost.Geometry (1.74) over a coordinate type T, instantiated for std::int64_t and double in
// peer_boost_int64.cpp and peer_boost_double.cpp. Counter-clockwise closed polygons with
// holes; a polygon set is a multi_polygon.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <string>
#include <type_traits>
#include <utility>

#include "peer.hpp"
#include "peer_conversion.hpp"

namespace edgeland::bench {

template <class T>
class BoostPeer final : public Peer {
  using BgPoint = boost::geometry::model::d2::point_xy<T>;
  using BgPolygon = boost::geometry::model::polygon<BgPoint, /*ClockWise=*/false, /*Closed=*/true>;
  using BgMulti = boost::geometry::model::multi_polygon<BgPolygon>;

  struct BoostShape final : Shape {
    BgMulti multi;
  };

  static Ring to_ring(const typename BgPolygon::ring_type& bg_ring) {
    Ring ring;
    ring.reserve(bg_ring.size());
    for (const BgPoint& p : bg_ring) {
      if constexpr (std::is_integral_v<T>) {
        ring.push_back({p.x(), p.y()});
      } else {
        ring.push_back({round_coord(p.x()), round_coord(p.y())});
      }
    }
    return as_open_ccw(std::move(ring));
  }

 public:
  explicit BoostPeer(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }

  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    auto shape = std::make_unique<BoostShape>();
    for (const Polygon& polygon : set) {
      BgPolygon bg;
      for (const Point64& p : polygon) {
        bg.outer().emplace_back(static_cast<T>(p.x), static_cast<T>(p.y));
      }
      bg.outer().push_back(bg.outer().front());
      shape->multi.push_back(std::move(bg));
    }
    return shape;
  }

  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    const BgMulti& a = static_cast<const BoostShape&>(subject).multi;
    const BgMulti& b = static_cast<const BoostShape&>(clip_shape).multi;
    auto out = std::make_unique<BoostShape>();
    switch (op) {
      case ClipOp::kUnion:
        boost::geometry::union_(a, b, out->multi);
        break;
      case ClipOp::kIntersection:
        boost::geometry::intersection(a, b, out->multi);
        break;
      case ClipOp::kDifference:
        boost::geometry::difference(a, b, out->multi);
        break;
      case ClipOp::kXor:
        boost::geometry::sym_difference(a, b, out->multi);
        break;
    }
    return out;
  }

  std::size_t vertex_count(const Shape& shape) const override {
    return boost::geometry::num_points(static_cast<const BoostShape&>(shape).multi);
  }

  PeerRings rings(const Shape& shape) const override {
    PeerRings out;
    for (const BgPolygon& polygon : static_cast<const BoostShape&>(shape).multi) {
      out.outers.push_back(to_ring(polygon.outer()));
      for (const auto& hole : polygon.inners()) out.holes.push_back(to_ring(hole));
    }
    return out;
  }

 private:
  std::string name_;
};

}  // namespace edgeland::bench
