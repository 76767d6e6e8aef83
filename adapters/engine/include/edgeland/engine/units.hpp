#pragma once
// Conversions between the landscape's exact integers and a game engine's floating-point units.
//
// THE ONLY FLOATING POINT of edgeland's installed headers: everything in kernel/, clip/, spatial/
// and game/ is integer and exact, and results never depend on what happens here. A game turns
// landscape points, ray hits and normals into engine units for drawing and physics, and engine
// positions back into landscape points for its next edit or query.
//
// THE ORIGIN RULE, one for every conversion: engine = (landscape - origin) / units_per_engine_unit,
// with `origin` exactly what the EngineUnits holds. An EngineUnits{} made by hand has the origin
// (0, 0), the landscape's own; the Box2D adapter's Terrain builds its EngineUnits with the world
// box's corner as the origin unless TerrainOptions::origin is given (an explicit (0, 0) too), and
// Terrain::units() is the one to pass on (make_debris_body), so debris lands where its island was
// in any world. Why an origin at all: a world near the int32 bound would lose every vertex to
// float rounding in the engine (Box2D asserts on such loops); relative to a near origin, engine
// coordinates stay as small as the world is wide (adapters/README.md, "Units and the origin").
#include <cmath>
#include <cstdint>

#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

struct EngineVec {
  double x = 0, y = 0;
  friend bool operator==(const EngineVec&, const EngineVec&) = default;
};

// A fraction as the nearest double (t of a MaterialCrossing, a ray parameter). Exact for
// numerators and denominators below 2^53; otherwise within a rounding or two.
inline double to_double(const Fraction& f) {
  return static_cast<double>(f.num) / static_cast<double>(f.den);
}

// An exact rational point as doubles (a hit point).
inline EngineVec to_double(const RationalPoint& p) {
  const double den = static_cast<double>(p.den);
  return {static_cast<double>(p.x_num) / den, static_cast<double>(p.y_num) / den};
}

// An exact, unnormalised direction (an edge's outward normal) as a unit vector; (0, 0) stays.
inline EngineVec unit_vector(Point64 d) {
  const double x = static_cast<double>(d.x), y = static_cast<double>(d.y);
  const double length = std::hypot(x, y);
  return length > 0 ? EngineVec{x / length, y / length} : EngineVec{};
}

// World <-> engine: engine = (world - origin) / units_per_engine_unit.
struct EngineUnits {
  Point64 origin;                    // the landscape point at the engine's (0, 0); default (0, 0)
  double units_per_engine_unit = 1;  // landscape units in one engine unit (metre): > 0

  EngineVec to_engine(Point64 p) const {
    return {static_cast<double>(p.x - origin.x) / units_per_engine_unit,
            static_cast<double>(p.y - origin.y) / units_per_engine_unit};
  }
  EngineVec to_engine(const RationalPoint& p) const {
    const EngineVec v = to_double(p);
    return {(v.x - static_cast<double>(origin.x)) / units_per_engine_unit,
            (v.y - static_cast<double>(origin.y)) / units_per_engine_unit};
  }
  double length_to_engine(double units) const { return units / units_per_engine_unit; }
  // The nearest landscape point to an engine position (ties away from zero); the caller keeps it
  // in range (clamp to the world box) before an edit or query takes it.
  Point64 to_world(EngineVec v) const {
    return {origin.x + std::llround(v.x * units_per_engine_unit),
            origin.y + std::llround(v.y * units_per_engine_unit)};
  }
  double to_world_length(double engine_length) const {
    return engine_length * units_per_engine_unit;
  }
};

}  // namespace edgeland
