#pragma once
// One interface over every clipping library in the comparison, so that each benchmark runs the
// same driver code on the same seeded inputs for every peer. Each peer lives in its own .cpp
// (CGAL alone takes ~40 s per translation unit; TOOLCHAIN.md pitfall 7).
//
// What is timed: apply(), i.e. from the peer's own input representation to its own output
// representation, including everything the library builds internally (Clipper's edge lists,
// CGAL's arrangements, edgeland's whole pipeline). Converting edgeland polygons into the
// peer's representation (load) and back to integers (rings) is never timed.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::bench {

// A polygon set in a peer's own representation; only that peer looks inside.
class Shape {
 public:
  virtual ~Shape() = default;
};

// A peer's result converted back to integer rings (see ring_check.hpp): every ring without
// its closing duplicate vertex, each coordinate rounded to the nearest integer (halves away
// from zero) and oriented counter-clockwise (orientation is a convention, not validity: GEOS
// returns clockwise shells). Holes are not assigned to their shells: no check needs that.
struct PeerRings {
  std::vector<Ring> outers;
  std::vector<Ring> holes;
};

class Peer {
 public:
  virtual ~Peer() = default;
  // Short, filter-friendly name used in benchmark names, e.g. "clipper1".
  virtual std::string name() const = 0;
  // A valid edgeland polygon set (hole-free CCW polygons, disjoint interiors) as a Shape.
  virtual std::unique_ptr<Shape> load(const PolygonSet& set) const = 0;
  // subject OP clip, both produced by load() or by an earlier apply() of the same peer.
  // Throws whatever the library throws.
  virtual std::unique_ptr<Shape> apply(ClipOp op, const Shape& subject,
                                       const Shape& clip) const = 0;
  // Output size (all rings), reported as a counter and keeping the result observable.
  virtual std::size_t vertex_count(const Shape& shape) const = 0;
  virtual PeerRings rings(const Shape& shape) const = 0;
  // Intersections the operation found, when the peer reports them (edgeland does); else 0.
  virtual std::size_t intersections(const Shape& /*result*/) const { return 0; }
};

// Factories, one per translation unit.
std::unique_ptr<Peer> make_edgeland_peer();
std::unique_ptr<Peer> make_edgeland_valid_peer();
std::unique_ptr<Peer> make_boost_int64_peer();
std::unique_ptr<Peer> make_boost_double_peer();
std::unique_ptr<Peer> make_clipper1_peer();
std::unique_ptr<Peer> make_geos_peer();
std::unique_ptr<Peer> make_cgal_epeck_peer();
std::unique_ptr<Peer> make_cgal_epick_peer();

// Every peer, edgeland (validating) first, then edgeland on ValidSets.
std::vector<std::unique_ptr<Peer>> make_all_peers();

}  // namespace edgeland::bench
