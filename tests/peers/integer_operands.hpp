#pragma once
// From a peer's decimal case to edgeland's integer input: every coordinate scaled by one power
// of ten for the whole case (both operands, so they keep their relative position) and rounded
// exactly (exact_decimal.hpp).
//   * fine: the smallest power that makes every coordinate an integer, lowered until every
//     coordinate satisfies |c| <= kCoordBound: as precise as the range allows;
//   * coarse: the largest power at which the case's extent is at most kCoarseExtent units,
//     only when it is below the fine power. Whole groups of vertices then round to one grid
//     point, edges collapse onto each other and rings turn inside out: the nastiest input for
//     a snap-rounding clipper, and what a game gets when it imports detailed art coarsely;
//   * peer: the power a data file names with `peer_scale` for a case, the grid the peer itself
//     rounds that case to (e.g. GEOS's snap-rounding tests at precision 1).
// The rounded rings may be invalid in every way (repeated points, spikes, self-crossings);
// the test turns them into valid sets with import_polygons / normalize.
#include <optional>
#include <string>
#include <vector>

#include "decimal_wkt.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "peer_case_file.hpp"

namespace edgeland::test {

inline constexpr int kCoarseExtent = 100;

enum class Scaling { kFine, kCoarse, kPeer };

// OGC polygons as the clipper's import_polygons takes them: element 0 the exterior.
using IntegerPolygons = std::vector<std::vector<Ring>>;

struct ScaledCase {
  PeerCase peer;
  Scaling scaling = Scaling::kFine;
  int power = 0;  // coordinates were multiplied by 10^power
  IntegerPolygons a, b;
  std::string test_name;  // file, case and scaling, as a GoogleTest parameter name
};

int fine_power(const DecimalGeometry& a, const DecimalGeometry& b);
std::optional<int> coarse_power(const DecimalGeometry& a, const DecimalGeometry& b);

// Each ring scaled and rounded; the closing point is dropped when it rounds onto the first
// (a ring that the peer left open stays open: edgeland's rings close implicitly).
IntegerPolygons to_integer_polygons(const DecimalGeometry& g, int power);

// The fine variant of a case, the coarse one when it differs, and the peer's own grid when
// the data file names one. Throws on unreadable WKT.
std::vector<ScaledCase> scaled_variants(const PeerCase& peer);

// All rings of all polygons, as written (for normalize under a fill rule).
std::vector<Ring> all_rings(const IntegerPolygons& polygons);

}  // namespace edgeland::test
