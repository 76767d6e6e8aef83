#pragma once
// Invariant checkers for the stages of the clip pipeline (clip/README.md), the expensive tier of
// the two in edgeland/kernel/assert.hpp: meant for the checked build, where run() calls each on
// the result of its stage before the next stage reads it. Each checks what its stage promises
// the next one, returns nothing when every rule holds, and otherwise throws std::logic_error
// through fail_stage: "<stage>: <rule>: <where, by index> (<file>:<line>)", for the first rule
// broken, in the order listed below. On valid operands a failure is a bug in the stage (or in
// the one before it). The validating clip() may feed the stages invalid operands; `guarded`
// (pipeline.hpp) validates them before reporting an internal error, so those still surface as
// InvalidInput.
//
// Cost: O(n log n) or linear in the stage's output, except check_fragments, which pays what
// noding pays for the same number of segments (candidate pairs from the same searches).
// Nothing is quadratic in the number of segments on inputs noding handles in near-linear time.
#include <cstdint>
#include <vector>

#include "assembly.hpp"
#include "input_edges.hpp"
#include "labeling.hpp"
#include "plane_graph.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

// Snap rounding ("snap rounding: ..."): `fragments` and `touched` as snap_round returned them
// for `edges` (touched after the pipeline's own additions, e.g. merged stretches).
// Structure (the plane graph numbers its vertices from fragment starts, and reads
// untouched segments from the input):
//   * sizes: touched and next have one entry per segment; next[s] names a segment;
//   * zero-length fragment: every listed fragment has a != b;
//   * parent out of range; parent order: listed fragments come in nondecreasing parent order;
//   * strays from its segment: both ends of a listed fragment lie in the closed unit square
//     centred at some point of its segment (so does all of it: that set is convex). Routes
//     stay within the pixels their segment meets; the locality of an operation (moved_boxes:
//     nothing beyond one unit of them changes) rests on it;
//   * end to end: a listed segment's fragments run from its start to its end, each starting
//     where the previous one ended (snap rounding never moves an input vertex);
//   * listed but untouched: an untouched segment must not be listed (the plane graph chains it
//     and never reads its fragments);
//   * untouched end: an untouched segment ends where its ring successor starts (a chain runs
//     on along the ring; an end that starts nothing is a vertex, so its segment is touched).
// Geometry, over every pair of fragments whose boxes overlap (listed ones, and each unlisted
// segment as its own fragment), classified exactly by kernel predicates:
//   * crossing: no two fragments cross properly (the graph would miss a vertex);
//   * endpoint inside: no fragment's end lies inside another (ditto);
//   * partial overlap: collinear fragments that share a stretch are the same segment (the
//     graph merges overlaps by their endpoints only);
//   * untouched contact: an untouched segment meets nothing but its ring neighbours, at their
//     common end (chain interior points must not be graph vertices).
void check_fragments(const EdgeList& edges, const std::vector<Fragment>& fragments,
                     const std::vector<std::uint8_t>& touched);

// The plane graph ("plane graph: ..."), what labeling and assembly index without checking:
//   * sizes: origin_of has an even size, chain one record per edge, mult_begin edges + 1,
//     around and turn_at one entry per half-edge, around_begin vertices + 1;
//   * vertex order: vertices strictly increasing (sorted, unique: ids compare like points);
//   * edge ends: from(e) < to(e), both vertex ids;
//   * multiplicity CSR: mult_begin starts at 0, is nondecreasing, ends at mults.size();
//   * multiplicity: every net != 0, channel 0 or 1, polygon >= 0 (-1 means "no owner"), and
//     within an edge strictly increasing by (channel, polygon) (one entry per tag);
//   * chain record: a chain (count > 0) lies within its ring, inside the segment list, and its
//     first segment's start and last segment's end are its edge's ends (reversed: swapped);
//   * around CSR: around_begin starts at 0, is nondecreasing, ends at the half-edge count;
//   * around: every half-edge appears exactly once, in its origin's range;
//   * zero first step: a half-edge's first step leaves its origin;
//   * same direction: no two half-edges leave a vertex in the same direction (they would
//     overlap: the graph would not be plane);
//   * angle order: around each vertex, first steps strictly counter-clockwise from angle 0
//     (kernel angle_less); labeling's rotations and assembly's turns rely on it;
//   * turn_at: turn_at[h] is the position, at target(h), of the half-edge just clockwise of
//     twin(h): the next half-edge of the face on h's left.
void check_plane_graph(const PlaneGraph& g);

// Labeling ("labeling: ..."): `left` from label_sides(g, mode, left) on a graph that passes
// check_plane_graph. What assembly trusts when it labels faces:
//   * size: one state per half-edge;
//   * state range: owners are polygons or -1 (none); counts (kOwnerAndCount's channel 1: valid
//     counter-clockwise rings) are >= 0; kWinding leaves channel 1 at 0. Assembly's labels
//     index tables by these values;
//   * face: every half-edge h has the state of the next half-edge of its left face,
//     left[around[turn_at[h]]] (a face has one state);
//   * crossing: the two sides of each edge differ exactly as its multiplicities say. Crossing
//     half-edge h from its right (left[twin]) to its left, with each net counted along h:
//     kWinding adds every net to channel 0 and keeps channel 1; a count channel
//     (kOwnerAndCount's channel 1) adds that channel's nets; an owner channel becomes the
//     smallest polygon of that channel with a positive net, else none (-1) if the owner has a
//     negative net, else stays. Checked across both half-edges of every edge;
//   * outer face: the face west of the smallest vertex with edges (the unbounded face: every
//     point of the graph is lexicographically at least that vertex) has empty_state(mode).
// Not checked: the state a nested component copies from below it (labeling's one point
// location per component). A wrong one shifts the whole component consistently, which only a
// second point location could see.
void check_labels(const PlaneGraph& g, LabelMode mode, const std::vector<SideState>& left);

// Assembly ("assembly: ..."), what hole splitting, canonical ordering and the caller take as
// given:
//   * labels: one label per output ring, none negative (-1 is "not in the result");
//   * ring size: at least 3 points;
//   * closing point repeated: a ring does not repeat its first point at its end (rings are
//     closed implicitly);
//   * repeated consecutive point (a zero-length edge);
//   * orientation: output rings and holed regions' outers counter-clockwise, holes clockwise
//     (kernel twice_signed_area; zero area is neither);
//   * repeated point: no ring visits a point twice (loops are split at repeated vertices);
//   * canonical: output rings start at their smallest point and have no vertex collinear with
//     its neighbours (only their order is left to sort_canonical);
//   * holed region: each has at least one outer and one hole, and a label >= 0;
//   * holed order: holed regions strictly increasing by label (one region per label).
void check_assembled(const Assembled& assembled);

}  // namespace edgeland::detail
