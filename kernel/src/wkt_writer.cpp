#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland {
namespace {

void append_ring(std::string& out, const Polygon& ring) {
  out += '(';
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Point64 p = ring[i % ring.size()];
    if (i != 0) out += ", ";
    out += std::to_string(p.x);
    out += ' ';
    out += std::to_string(p.y);
  }
  out += ')';
}

}  // namespace

std::string to_wkt(const Polygon& polygon) {
  if (polygon.empty()) return "POLYGON EMPTY";
  std::string out = "POLYGON (";
  append_ring(out, polygon);
  out += ')';
  return out;
}

std::string to_wkt(const PolygonSet& set) {
  std::string out = "MULTIPOLYGON ";
  std::size_t written = 0;
  for (const Polygon& p : set) {
    if (p.empty()) continue;
    out += written++ == 0 ? "((" : ", (";
    append_ring(out, p);
    out += ')';
  }
  out += written == 0 ? "EMPTY" : ")";
  return out;
}

}  // namespace edgeland
