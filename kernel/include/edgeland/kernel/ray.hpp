#pragma once
// First hit of a ray with a ring's boundary (thesis 2.4.2), with back-face culling and the
// convex early exit.
//
// Magnitudes (why the parameter is a Fraction and how it is compared): with |c| <= kCoordBound
// = B and |direction component| <= kMaxRayDirection = 2B + 1, every quantity computed per
// edge is a cross or dot product of two vectors whose components are at most 2B + 1, hence
// below 2 (2B + 1)^2 < 2^65: far inside Int128. Comparing the parameters of two edges by
// cross-multiplication, however, needs up to 2^130, which does not fit Int128 (< 2^127), so
// hits are compared with edgeland::compare (fraction.hpp), exact through 256-bit products.
// The hit point's numerators are below B * 2^65 + 2^65 * (2B + 1) < 2^98.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "edgeland/kernel/convexity.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

// Largest allowed |dx|, |dy| of a ray direction: room for the difference of two in-range
// points (2B) with one to spare.
inline constexpr std::int64_t kMaxRayDirection = 2 * kCoordBound + 1;

// The points origin + t * (dx, dy) for t >= 0. The origin must be in range and
// |dx|, |dy| <= kMaxRayDirection. A zero direction makes the ray the single point origin.
struct Ray {
  Point64 origin;
  std::int64_t dx = 0;
  std::int64_t dy = 0;
};

// Which edges to skip, for a COUNTER-CLOCKWISE ring (the library's orientation; for a
// clockwise ring swap the two culling modes). An edge e "faces" the ray when the ray goes
// from its outer side to its inner side: cross(direction, e) < 0. Edges parallel to the ray
// are never culled.
enum class RayCulling : std::uint8_t {
  kNoCulling,  // (not kNone: that is validate.hpp's "no index")
  // Skip back faces (edges the ray leaves the interior through). When the origin is
  // strictly outside a simple ring, the first hit is at the same t as with kNoCulling (the edge
  // reported may differ where edges share that point).
  kOriginOutside,
  // Skip front faces (edges the ray enters through). When the origin is strictly inside
  // a simple ring, the first hit is at the same t as with kNoCulling.
  kOriginInside,
};

// Where the ray first meets the closed segment e: the smallest t >= 0 with origin + t *
// direction on e, or nullopt when it misses. A ray running along e meets it at its nearer end
// (t = 0 when the origin is on e); a zero direction meets e only when the origin is on it.
// Axis-parallel rays (the clipper's probes) reject segments off their line by comparisons.
// O(1).
EDGELAND_EXPORT std::optional<Fraction> ray_contact(const Ray& ray, const Segment& e) noexcept;

// The point origin + t * direction, exactly (den = t.den). O(1).
EDGELAND_EXPORT RationalPoint ray_point(const Ray& ray, const Fraction& t) noexcept;

// THE nearest-hit primitive: segments are offered one by one and the nearest contact along the
// ray is kept (ties: the first offered). first_hit() below and the clipper's probes
// (labeling's look below a component, hole bridging's look west) find their first hit through
// it, so "first along a ray" has one definition and one proof (theorems ray_edge_int128 and
// ray_point_*_int128). (The landscape's queries along a segment need every crossing, in order,
// not the first: segment_crossings.hpp.)
class NearestHit {
 public:
  enum class Offer : std::uint8_t {
    kMissed,   // the ray misses the segment
    kFarther,  // met, but not nearer than the hit so far
    kNearest,  // met nearer than every earlier offer: now the hit
  };
  // Whether a segment through the ray's origin counts (its contact is at t = 0). The clipper's
  // probes start at a vertex and look past what passes through it: kExcluded makes the ray
  // open at its origin, so such segments are missed.
  enum class Origin : std::uint8_t { kIncluded, kExcluded };
  explicit NearestHit(const Ray& ray, Origin origin = Origin::kIncluded) noexcept
      : ray_(ray), open_(origin == Origin::kExcluded) {}
  Offer offer(const Segment& e) noexcept;
  bool found() const noexcept { return found_; }
  const Fraction& t() const noexcept { return t_; }                     // when found()
  RationalPoint point() const noexcept { return ray_point(ray_, t_); }  // when found()

 private:
  Ray ray_;
  bool open_;
  bool found_ = false;
  Fraction t_;
};

struct RayHit {
  std::size_t edge = 0;  // edge i runs from vertex i to vertex (i + 1) mod n
  Fraction t;            // the hit is origin + t * direction, t >= 0 (exact, not reduced)
  RationalPoint point;   // the same point, exactly
};

// The first point where the ray meets a (closed) edge that is not culled: the smallest t;
// among edges sharing that smallest t (a vertex, or collinear edges), the lowest index.
// A ray running along an edge hits it where it first touches it (t = 0 if the origin is on
// it). nullopt when the ray misses every edge that is not culled.
//
// With RingShape::kConvex (ring convex and counter-clockwise, see is_convex) the scan stops
// once the edges met so far form all the contact the ray can have with a convex boundary:
// with culling, the first run of consecutive hit edges; without, two such runs or one run
// containing a collinear edge (thesis 2.4.1, 2.4.2). The result equals the full scan's.
//
// O(n) (kConvex with culling: stops right after the hit, about half the edges on average).
EDGELAND_EXPORT std::optional<RayHit> first_hit(const Ray& ray, const Ring& ring,
                                                RayCulling culling = RayCulling::kNoCulling,
                                                RingShape shape = RingShape::kGeneral);

}  // namespace edgeland
