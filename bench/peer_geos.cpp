// GEOS 3.11 through its reentrant C API (geos_c.h, the *_r functions; Debian ships no C++
// headers). Double coordinates, OverlayNG (the default overlay since 3.9).
#include <geos_c.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "peer.hpp"
#include "peer_conversion.hpp"

namespace edgeland::bench {
namespace {

struct GeosShape final : Shape {
  GEOSContextHandle_t context = nullptr;
  GEOSGeometry* geometry = nullptr;
  GeosShape(GEOSContextHandle_t ctx, GEOSGeometry* g) : context(ctx), geometry(g) {}
  GeosShape(const GeosShape&) = delete;
  GeosShape& operator=(const GeosShape&) = delete;
  ~GeosShape() override { GEOSGeom_destroy_r(context, geometry); }
};

void remember_error(const char* message, void* userdata) {
  *static_cast<std::string*>(userdata) = message;
}

class GeosPeer final : public Peer {
 public:
  GeosPeer() : context_(GEOS_init_r()) {
    GEOSContext_setErrorMessageHandler_r(context_, remember_error, &last_error_);
  }
  GeosPeer(const GeosPeer&) = delete;
  GeosPeer& operator=(const GeosPeer&) = delete;
  // Shapes must not outlive their peer (the driver keeps the peer alive throughout).
  ~GeosPeer() override { GEOS_finish_r(context_); }

  std::string name() const override { return "geos"; }

  std::unique_ptr<Shape> load(const PolygonSet& set) const override {
    std::vector<GEOSGeometry*> polygons;
    polygons.reserve(set.size());
    for (const Polygon& polygon : set) {
      const auto n = static_cast<unsigned>(polygon.size());
      GEOSCoordSequence* seq = GEOSCoordSeq_create_r(context_, n + 1, 2);
      for (unsigned i = 0; i <= n; ++i) {
        const Point64& p = polygon[i % n];
        GEOSCoordSeq_setXY_r(context_, seq, i, static_cast<double>(p.x), static_cast<double>(p.y));
      }
      GEOSGeometry* shell = GEOSGeom_createLinearRing_r(context_, seq);
      polygons.push_back(GEOSGeom_createPolygon_r(context_, shell, nullptr, 0));
    }
    GEOSGeometry* multi = GEOSGeom_createCollection_r(context_, GEOS_MULTIPOLYGON, polygons.data(),
                                                      static_cast<unsigned>(polygons.size()));
    return std::make_unique<GeosShape>(context_, multi);
  }

  std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                               const Shape& clip_shape) const override {
    const GEOSGeometry* a = static_cast<const GeosShape&>(subject).geometry;
    const GEOSGeometry* b = static_cast<const GeosShape&>(clip_shape).geometry;
    GEOSGeometry* result = nullptr;
    switch (op) {
      case ClipOp::kUnion:
        result = GEOSUnion_r(context_, a, b);
        break;
      case ClipOp::kIntersection:
        result = GEOSIntersection_r(context_, a, b);
        break;
      case ClipOp::kDifference:
        result = GEOSDifference_r(context_, a, b);
        break;
      case ClipOp::kXor:
        result = GEOSSymDifference_r(context_, a, b);
        break;
    }
    if (result == nullptr) throw std::runtime_error("GEOS: " + last_error_);
    return std::make_unique<GeosShape>(context_, result);
  }

  std::size_t vertex_count(const Shape& shape) const override {
    return static_cast<std::size_t>(
        GEOSGetNumCoordinates_r(context_, static_cast<const GeosShape&>(shape).geometry));
  }

  PeerRings rings(const Shape& shape) const override {
    PeerRings out;
    collect(static_cast<const GeosShape&>(shape).geometry, out);
    return out;
  }

 private:
  Ring to_ring(const GEOSGeometry* ring) const {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(context_, ring);
    unsigned size = 0;
    GEOSCoordSeq_getSize_r(context_, seq, &size);
    Ring out;
    out.reserve(size);
    for (unsigned i = 0; i < size; ++i) {
      double x = 0, y = 0;
      GEOSCoordSeq_getXY_r(context_, seq, i, &x, &y);
      out.push_back({round_coord(x), round_coord(y)});
    }
    return as_open_ccw(std::move(out));
  }

  // Polygons, multipolygons and collections of them (an empty result is an empty collection).
  void collect(const GEOSGeometry* g, PeerRings& out) const {
    const int type = GEOSGeomTypeId_r(context_, g);
    if (type == GEOS_POLYGON) {
      if (GEOSisEmpty_r(context_, g) == 1) return;
      out.outers.push_back(to_ring(GEOSGetExteriorRing_r(context_, g)));
      const int holes = GEOSGetNumInteriorRings_r(context_, g);
      for (int i = 0; i < holes; ++i)
        out.holes.push_back(to_ring(GEOSGetInteriorRingN_r(context_, g, i)));
    } else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
      const int n = GEOSGetNumGeometries_r(context_, g);
      for (int i = 0; i < n; ++i) collect(GEOSGetGeometryN_r(context_, g, i), out);
    } else {
      throw std::runtime_error("GEOS returned a non-polygonal geometry");
    }
  }

  GEOSContextHandle_t context_;
  mutable std::string last_error_;
};

}  // namespace

std::unique_ptr<Peer> make_geos_peer() { return std::make_unique<GeosPeer>(); }

}  // namespace edgeland::bench
