// Properties of the WKT reader: it reads back what the kernel's writer writes, and on any
// bytes at all it either returns or throws WktError (no crash, no other exception, no hang).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <string>
#include <vector>

#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland {
namespace {

rc::Gen<std::int64_t> coordinate() {
  return rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-kCoordBound, kCoordBound + 1),
                        rc::gen::inRange<std::int64_t>(-3, 4),
                        rc::gen::element(-kCoordBound, kCoordBound, std::int64_t{0}));
}

rc::Gen<Ring> ring() {
  const auto point = rc::gen::construct<Point64>(coordinate(), coordinate());
  return rc::gen::suchThat(rc::gen::container<Ring>(point),
                           [](const Ring& r) { return !r.empty(); });
}

// Either a result or a WktError; anything else escapes and fails the property.
void read_or_reject(const std::string& text) {
  try {
    read_wkt(text);
  } catch (const WktError& error) {
    RC_ASSERT(std::string(error.what()).find('\n') == std::string::npos);
  }
}

RC_GTEST_PROP(WktReaderProperty, ReadsBackWhatTheKernelWriterWrites, ()) {
  const auto set = *rc::gen::container<PolygonSet>(ring());
  const WktGeometry g = read_wkt(to_wkt(set));
  RC_ASSERT(g.type == WktGeometry::Type::kMultiPolygon);
  RC_ASSERT(g.polygons.size() == set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    RC_ASSERT(g.polygons[i].exterior == set[i]);
    RC_ASSERT(g.polygons[i].holes.empty());
  }
}

RC_GTEST_PROP(WktReaderProperty, ReadsBackASinglePolygon, ()) {
  const Ring r = *ring();
  const WktGeometry g = read_wkt(to_wkt(Polygon(r)));
  RC_ASSERT(g.type == WktGeometry::Type::kPolygon);
  RC_ASSERT(g.polygons.size() == 1u);
  RC_ASSERT(g.polygons[0].exterior == r);
}

RC_GTEST_PROP(WktReaderProperty, ArbitraryBytesAreReadOrRejected, (const std::string& bytes)) {
  read_or_reject(bytes);
}

RC_GTEST_PROP(WktReaderProperty, TextFromTheWktAlphabetIsReadOrRejected, ()) {
  // Mostly the characters WKT is made of, so the checks behind the byte filter are reached.
  const auto text = *rc::gen::container<std::string>(
      rc::gen::element('(', ')', ',', ' ', '\n', '0', '1', '7', '-', '+', '.', 'e', 'P', 'O', 'L',
                       'Y', 'G', 'N', 'M', 'U', 'T', 'I', 'E', 'Z'));
  read_or_reject(text);
  read_or_reject("POLYGON " + text);
  read_or_reject("MULTIPOLYGON (" + text);
}

RC_GTEST_PROP(WktReaderProperty, OneEditedByteOfAValidTextIsReadOrRejected, ()) {
  std::string text =
      to_wkt(PolygonSet{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 0}, {30, 0}, {25, 9}}});
  const auto at = *rc::gen::inRange<std::size_t>(0, text.size());
  const auto byte = *rc::gen::arbitrary<char>();
  const auto erase = *rc::gen::arbitrary<bool>();
  if (erase) {
    text.erase(at, 1);
  } else {
    text[at] = byte;
  }
  read_or_reject(text);
}

}  // namespace
}  // namespace edgeland
