#pragma once
// CGAL 5.5 Boolean_set_operations_2 over kernel K (Epeck in peer_cgal_epeck.cpp, Epick in
// peer_cgal_epick.cpp). A shape is the list of polygons with holes that CGAL hands out; apply()
// builds a Polygon_set_2 of each operand (an arrangement), runs the operation and extracts the
// result, so like every other peer it goes from polygons to polygons.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "peer.hpp"
#include "peer_conversion.hpp"

namespace edgeland::bench {

template <class K>
class CgalPeer final : public Peer {
  using CgalPolygon = CGAL::Polygon_2<K>;
  using CgalPwh = CGAL::Polygon_with_holes_2<K>;
  using CgalSet = CGAL::Polygon_set_2<K>;

  struct CgalShape final : Shape {
    std::vector<CgalPwh> polygons;
  };

  static Ring to_ring(const CgalPolygon& polygon) {
    Ring ring;
    ring.reserve(polygon.size());
    for (auto it = polygon.vertices_begin(); it != polygon.vertices_end(); ++it) {
      ring.push_back(
          {round_coord(CGAL::to_double(it->x())), round_coord(CGAL::to_double(it->y()))});
    }
    return as_open_ccw(std::move(ring));
  }

  static CgalSet as_set(const CgalShape& shape) {
    CgalSet set;
    // The members of a valid set have disjoint interiors: bulk insertion, no overlay needed.
    set.insert(shape.polygons.begin(), shape.polygons.end());
    return set;
  }

 public:
  explicit CgalPeer(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }

  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    auto shape = std::make_unique<CgalShape>();
    for (const Polygon& polygon : set) {
      CgalPolygon cgal;
      for (const Point64& p : polygon) {
        cgal.push_back(typename K::Point_2(static_cast<double>(p.x), static_cast<double>(p.y)));
      }
      shape->polygons.emplace_back(std::move(cgal));
    }
    return shape;
  }

  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    CgalSet a = as_set(static_cast<const CgalShape&>(subject));
    const CgalSet b = as_set(static_cast<const CgalShape&>(clip_shape));
    switch (op) {
      case ClipOp::kUnion:
        a.join(b);
        break;
      case ClipOp::kIntersection:
        a.intersection(b);
        break;
      case ClipOp::kDifference:
        a.difference(b);
        break;
      case ClipOp::kXor:
        a.symmetric_difference(b);
        break;
    }
    auto out = std::make_unique<CgalShape>();
    a.polygons_with_holes(std::back_inserter(out->polygons));
    return out;
  }

  std::size_t vertex_count(const Shape& shape) const override {
    std::size_t n = 0;
    for (const CgalPwh& pwh : static_cast<const CgalShape&>(shape).polygons) {
      n += pwh.outer_boundary().size();
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) n += h->size();
    }
    return n;
  }

  PeerRings rings(const Shape& shape) const override {
    PeerRings out;
    for (const CgalPwh& pwh : static_cast<const CgalShape&>(shape).polygons) {
      out.outers.push_back(to_ring(pwh.outer_boundary()));
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) out.holes.push_back(to_ring(*h));
    }
    return out;
  }

 private:
  std::string name_;
};

}  // namespace edgeland::bench
