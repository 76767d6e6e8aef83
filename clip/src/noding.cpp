#include "noding.hpp"

#include <algorithm>

#include "candidate_pairs.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

void split_if_interior(Contacts& c, std::uint32_t seg, const Segment& s, Point64 p) {
  if (p != s.a && p != s.b) c.splits.emplace_back(seg, p);
}

// s and t lie on one horizontal (flat) or vertical line: they meet along the interval
// [lo, hi] of that line's coordinate where their ranges overlap, if any.
Meeting collinear_axis_contact(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                               bool flat, Contacts& c) {
  auto along = [flat](Point64 p) { return flat ? p.x : p.y; };
  const std::int64_t lo =
      std::max(std::min(along(s.a), along(s.b)), std::min(along(t.a), along(t.b)));
  const std::int64_t hi =
      std::min(std::max(along(s.a), along(s.b)), std::max(along(t.a), along(t.b)));
  if (lo > hi) return Meeting::kNone;
  auto at = [&](std::int64_t v) { return flat ? Point64{v, s.a.y} : Point64{s.a.x, v}; };
  const Point64 from = at(lo), to = at(hi);
  if (lo == hi && (from == s.a || from == s.b) && (from == t.a || from == t.b))
    return Meeting::kSharedEndpoint;
  ++c.intersections;
  split_if_interior(c, i, s, from);
  split_if_interior(c, j, t, from);
  if (hi != lo) {
    ++c.overlaps;
    split_if_interior(c, i, s, to);
    split_if_interior(c, j, t, to);
  }
  return Meeting::kOther;
}

// A proper crossing at rational point x: a split of both segments when x is an integer point,
// else a hot pixel. Rounded once; the point is an integer exactly when the rounding is exact.
void crossing_contact(const RationalPoint& x, std::uint32_t i, std::uint32_t j, Contacts& c) {
  const Point64 p = round_to_grid(x);
  if (is_exactly(x, p)) {
    c.splits.emplace_back(i, p);
    c.splits.emplace_back(j, p);
  } else {
    c.hot.push_back(p);
  }
}

// s and t are perpendicular axis-parallel segments (s_flat: s is the horizontal one). They can
// only meet at one integer point, the vertical one's x and the horizontal one's y. (A common
// endpoint of both was answered by the caller.)
Meeting perpendicular_axis_contact(const Segment& s, std::uint32_t i, const Segment& t,
                                   std::uint32_t j, bool s_flat, Contacts& c) {
  const Segment& h = s_flat ? s : t;
  const Segment& v = s_flat ? t : s;
  const Point64 p{v.a.x, h.a.y};
  if (!segment_box(h).contains(p) || !segment_box(v).contains(p)) return Meeting::kNone;
  ++c.intersections;
  split_if_interior(c, i, s, p);
  split_if_interior(c, j, t, p);
  return Meeting::kOther;
}

// Any other pair, through the kernel's exact classification: a crossing at a non-integer point
// becomes a hot pixel, every other contact point splits the segments it is interior to.
Meeting general_contact(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                        Contacts& c) {
  const SegmentIntersection r = intersect(s, t);
  switch (r.relation) {
    case SegmentRelation::kDisjoint:
      return Meeting::kNone;
    case SegmentRelation::kTouching: {
      // Touching points are endpoints: den is 1 (no 128-bit division needed).
      const Point64 p{static_cast<std::int64_t>(r.point.x_num),
                      static_cast<std::int64_t>(r.point.y_num)};
      if ((p == s.a || p == s.b) && (p == t.a || p == t.b)) return Meeting::kSharedEndpoint;
      ++c.intersections;
      split_if_interior(c, i, s, p);
      split_if_interior(c, j, t, p);
      return Meeting::kOther;
    }
    case SegmentRelation::kOverlapping:
      ++c.intersections;
      ++c.overlaps;
      for (Point64 p : {r.overlap_from, r.overlap_to}) {
        split_if_interior(c, i, s, p);
        split_if_interior(c, j, t, p);
      }
      return Meeting::kOther;
    case SegmentRelation::kCrossing:
      ++c.intersections;
      crossing_contact(r.point, i, j, c);
      return Meeting::kOther;
  }
  return Meeting::kOther;  // Not reached by tests: the switch covers every SegmentRelation.
}

}  // namespace

Meeting classify_pair(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                      Contacts& c) {
  // The same segment twice (shared edges of neighbouring polygons, the common case in a
  // partition): an overlap whose ends are both segments' ends, so nothing to split.
  if ((s.a == t.b && s.b == t.a) || (s.a == t.a && s.b == t.b)) {
    ++c.intersections;
    ++c.overlaps;
    return Meeting::kOther;
  }
  // Ring neighbours share an endpoint: unless they are collinear that is their only contact.
  if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) {
    const Point64 t_other = (t.a == s.a || t.a == s.b) ? t.b : t.a;
    if (orientation(s.a, s.b, t_other) != Orientation::kCollinear) return Meeting::kSharedEndpoint;
  }
  // Axis-parallel pairs (tiles, boxes, cell cuts: the common case of rectilinear inputs) are
  // decided without the rational construction.
  const bool s_flat = s.a.y == s.b.y, t_flat = t.a.y == t.b.y;
  const bool s_upright = s.a.x == s.b.x, t_upright = t.a.x == t.b.x;
  if ((s_flat && t_upright) || (t_flat && s_upright))
    return perpendicular_axis_contact(s, i, t, j, s_flat, c);
  // Two horizontal or two vertical segments: on different lines they are apart, on one line
  // they share an interval of it (tiles side by side).
  if ((s_flat && t_flat) || (s_upright && t_upright)) {
    if (s_flat ? s.a.y != t.a.y : s.a.x != t.a.x) return Meeting::kNone;
    return collinear_axis_contact(s, i, t, j, s_flat, c);
  }
  return general_contact(s, i, t, j, c);
}

namespace {

// Thrown by the pair visit to stop noding: at the first contact proving an operand invalid, or
// once the overlapping pairs pass their budget.
struct StopNoding {
  bool overlap_heavy;
};

// Whether two segments of different rings of one operand meet in a way no valid set allows:
// crossing properly (each ring's inside lies on one side of its edge, so near the crossing the
// insides overlap), or overlapping along a stretch in the same direction (both insides on the
// same side of it). Exact; only asked of pairs that meet other than at shared endpoints.
bool overlap_proof(const Segment& s, const Segment& t) {
  const Orientation o1 = orientation(s.a, s.b, t.a), o2 = orientation(s.a, s.b, t.b);
  if (o1 == Orientation::kCollinear && o2 == Orientation::kCollinear) {
    const bool along_x = s.a.x != s.b.x;
    auto at = [along_x](Point64 p) { return along_x ? p.x : p.y; };
    const std::int64_t lo = std::max(std::min(at(s.a), at(s.b)), std::min(at(t.a), at(t.b)));
    const std::int64_t hi = std::min(std::max(at(s.a), at(s.b)), std::max(at(t.a), at(t.b)));
    const bool same_way = (at(s.b) > at(s.a)) == (at(t.b) > at(t.a));
    return lo < hi && same_way;
  }
  if (static_cast<int>(o1) * static_cast<int>(o2) >= 0) return false;
  const Orientation o3 = orientation(t.a, t.b, s.a), o4 = orientation(t.a, t.b, s.b);
  return static_cast<int>(o3) * static_cast<int>(o4) < 0;
}

// Ring of each segment (rings occupy consecutive ids): needed to skip the pairs of one ring on
// the grid walk when rings are simple, and to see a ring meet itself when screening.
void number_rings(const std::vector<std::uint32_t>& next, std::vector<std::uint32_t>& ring_of) {
  ring_of.resize(next.size());
  for (std::uint32_t s = 0, ring = 0; s < ring_of.size(); ++s) {
    if (s > 0 && next[s - 1] != s) ring = s;
    ring_of[s] = ring;
  }
}

// The visit of one candidate pair: classifies it, records what it finds, stops noding when
// the screen or the overlap budget says so.
class PairVisit {
 public:
  PairVisit(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
            const std::vector<std::uint32_t>& ring_of, const NodingOptions& options, Contacts& c)
      : segments_(segments), next_(next), ring_of_(ring_of), options_(options), c_(c) {}

  void operator()(std::uint32_t i, std::uint32_t j) const {
    const Meeting m = classify_pair(segments_[i], i, segments_[j], j, c_);
    if (m == Meeting::kNone) return;
    const bool neighbours = next_[i] == j || next_[j] == i;
    if (options_.screen_channel && proves_invalid(i, j, m, neighbours)) throw StopNoding{false};
    if (c_.overlaps > options_.overlap_budget) throw StopNoding{true};
    if (m == Meeting::kSharedEndpoint && neighbours) return;
    c_.touched[i] = c_.touched[j] = true;
  }

 private:
  // Screening: two segments of one ring meeting other than as neighbours at their shared
  // endpoint, or of two rings of one operand overlapping (overlap_proof).
  bool proves_invalid(std::uint32_t i, std::uint32_t j, Meeting m, bool neighbours) const {
    if (ring_of_[i] == ring_of_[j]) return m == Meeting::kOther || !neighbours;
    return m == Meeting::kOther && (*options_.screen_channel)[i] == (*options_.screen_channel)[j] &&
           overlap_proof(segments_[i], segments_[j]);
  }

  const std::vector<Segment>& segments_;
  const std::vector<std::uint32_t>& next_;
  const std::vector<std::uint32_t>& ring_of_;
  const NodingOptions& options_;
  Contacts& c_;
};

// Every candidate pair visited once (candidate_pairs.hpp). A grid walked on short runs is left
// in search.near for snap rounding's point queries.
void visit_candidate_pairs(const std::vector<Segment>& segments, SegmentSearch& search, bool walk,
                           bool simple_rings, const std::vector<std::uint32_t>& ring_of,
                           const PairVisit& visit) {
  std::optional<SegmentGrid>& walked = search.near.grid();
  if (walk) walked.emplace(segments);
  for_each_candidate_pair(segments, search.index, walked ? &*walked : nullptr, simple_rings,
                          ring_of.data(), visit);
  if (walked) walked->drop_pair_walk();  // snap rounding only asks it for boxes
}

}  // namespace

Contacts find_contacts(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
                       SegmentSearch& search, const NodingOptions& options) {
  Contacts c;
  c.touched.assign(segments.size(), false);
  const bool walk = runs_are_short(search.index, segments.size());
  const bool screening = options.screen_channel != nullptr;
  ScratchVector<std::uint32_t> ring_of;
  if (walk || screening) number_rings(next, ring_of);
  try {
    visit_candidate_pairs(segments, search, walk, options.simple_rings && !screening, ring_of,
                          PairVisit(segments, next, ring_of, options, c));
  } catch (const StopNoding& stop) {
    (stop.overlap_heavy ? c.overlap_heavy : c.operand_invalid) = true;
  }
  return c;
}

}  // namespace edgeland::detail
