#include "collinear_merge.hpp"

#include <algorithm>
#include <numeric>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

// An edge as the stretch lo -> hi (lo < hi lexicographically) and the weight it adds in that
// direction. Directions hi - lo all lie in one half-plane, so edges of one line share one.
struct Stretch {
  Point64 lo, hi;
  std::int32_t weight;
  std::uint8_t channel;
  std::int32_t polygon;
};

Stretch stretch_of(const EdgeList& in, std::uint32_t i) {
  const Segment& s = in.segments[i];
  const std::int32_t w = in.weight_of(i);
  return s.a < s.b ? Stretch{s.a, s.b, w, in.channel[i], in.polygon[i]}
                   : Stretch{s.b, s.a, -w, in.channel[i], in.polygon[i]};
}

Point64 direction(const Stretch& s) { return {s.hi.x - s.lo.x, s.hi.y - s.lo.y}; }

// Whether t lies on the line of s (exact: one direction comparison and one orientation).
bool same_line(const Stretch& s, const Stretch& t) {
  return !angle_less(direction(s), direction(t)) && !angle_less(direction(t), direction(s)) &&
         orientation(s.lo, s.hi, t.lo) == Orientation::kCollinear;
}

// A strict weak order that puts the edges of one (channel, polygon, line) together, in order of
// their lo along the line: by tag, then direction, then the line's offset (parallel lines are
// ordered by which side of one the other lies: a linear order up to a positive factor), then lo.
bool line_order(const Stretch& s, const Stretch& t) {
  if (s.channel != t.channel) return s.channel < t.channel;
  if (s.polygon != t.polygon) return s.polygon < t.polygon;
  const Point64 ds = direction(s), dt = direction(t);
  if (angle_less(ds, dt)) return true;
  if (angle_less(dt, ds)) return false;
  const Orientation side = orientation(s.lo, s.hi, t.lo);
  if (side != Orientation::kCollinear) return side == Orientation::kCounterClockwise;
  return s.lo < t.lo;
}

// One overlap component's elementary intervals with their summed weights, appended to `out`.
// Every point of the component's span is covered (the members are linked by shared stretches),
// so each interval between consecutive end points carries at least one member.
void append_intervals(const std::vector<Stretch>& members, MergedEdges& out) {
  struct End {
    Point64 at;
    std::int32_t weight;  // added to the running sum at `at`
  };
  std::vector<End> ends;
  ends.reserve(2 * members.size());
  for (const Stretch& m : members) {
    ends.push_back({m.lo, m.weight});
    ends.push_back({m.hi, -m.weight});
  }
  std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) { return x.at < y.at; });
  std::int64_t sum = 0;
  for (std::size_t k = 0; k < ends.size();) {
    const Point64 at = ends[k].at;
    for (; k < ends.size() && ends[k].at == at; ++k) sum += ends[k].weight;
    if (k == ends.size()) break;
    const auto s = static_cast<std::uint32_t>(out.edges.size());
    out.edges.segments.push_back({at, ends[k].at});
    out.edges.channel.push_back(members.front().channel);
    out.edges.polygon.push_back(members.front().polygon);
    out.edges.next.push_back(s);
    out.edges.weight.push_back(static_cast<std::int32_t>(sum));
    out.unchained.push_back(1);
  }
}

// Marks every edge that belongs to an overlap component of two or more edges, and appends the
// components' intervals to `out`.
std::vector<std::uint8_t> merge_components(const EdgeList& in, MergedEdges& out) {
  std::vector<Stretch> stretches(in.size());
  for (std::uint32_t i = 0; i < in.size(); ++i) stretches[i] = stretch_of(in, i);
  std::vector<std::uint32_t> order(in.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    return line_order(stretches[i], stretches[j]) ||
           (!line_order(stretches[j], stretches[i]) && i < j);
  });
  std::vector<std::uint8_t> merged(in.size(), 0);
  std::vector<Stretch> members;
  for (std::size_t k = 0; k < order.size();) {
    const Stretch& first = stretches[order[k]];
    std::size_t end = k + 1;
    Point64 reach = first.hi;  // along the line, members after k start before reach to overlap
    for (; end < order.size(); ++end) {
      const Stretch& t = stretches[order[end]];
      if (t.channel != first.channel || t.polygon != first.polygon || !same_line(first, t) ||
          !(t.lo < reach))
        break;
      reach = std::max(reach, t.hi);
    }
    if (end - k > 1) {
      members.clear();
      for (std::size_t m = k; m < end; ++m) {
        members.push_back(stretches[order[m]]);
        merged[order[m]] = 1;
      }
      append_intervals(members, out);
    }
    k = end;
  }
  return merged;
}

// Appends in's edges at ring positions [from, from + count) of ring [b, b + len) as one open
// run: consecutive ids, the last one's next back at the first (rings occupy consecutive ids).
void append_run(const EdgeList& in, std::uint32_t b, std::uint32_t len, std::uint32_t from,
                std::uint32_t count, bool open, MergedEdges& out) {
  const auto first = static_cast<std::uint32_t>(out.edges.size());
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t i = b + (from + k) % len;
    out.edges.segments.push_back(in.segments[i]);
    out.edges.channel.push_back(in.channel[i]);
    out.edges.polygon.push_back(in.polygon[i]);
    out.edges.next.push_back(k + 1 == count ? first : first + k + 1);
    out.edges.weight.push_back(in.weight_of(i));
    out.unchained.push_back(open && (k == 0 || k + 1 == count));
  }
}

// The edges of ring [b, b + len) that were not merged: the whole ring as it was, or its
// maximal runs between merged edges.
void append_ring_rest(const EdgeList& in, std::uint32_t b, std::uint32_t len,
                      const std::vector<std::uint8_t>& merged, MergedEdges& out) {
  std::uint32_t start = len;  // a merged position, if any
  for (std::uint32_t k = 0; k < len && start == len; ++k)
    if (merged[b + k]) start = k;
  if (start == len) return append_run(in, b, len, 0, len, false, out);
  for (std::uint32_t k = 1; k <= len;) {  // positions after `start`, cyclically
    if (merged[b + (start + k) % len]) {
      ++k;
      continue;
    }
    std::uint32_t count = 0;
    while (k + count < len && !merged[b + (start + k + count) % len]) ++count;
    append_run(in, b, len, start + k, count, true, out);
    k += count;
  }
}

}  // namespace

MergedEdges merge_collinear_overlaps(const EdgeList& in) {
  MergedEdges out;
  MergedEdges intervals;
  const std::vector<std::uint8_t> merged = merge_components(in, intervals);
  const auto n = static_cast<std::uint32_t>(in.size());
  for (std::uint32_t b = 0; b < n;) {
    std::uint32_t e = b;
    while (in.next[e] == e + 1) ++e;  // the ring occupies [b, e]
    append_ring_rest(in, b, e - b + 1, merged, out);
    b = e + 1;
  }
  const auto base = static_cast<std::uint32_t>(out.edges.size());
  for (std::uint32_t k = 0; k < intervals.edges.size(); ++k) {
    out.edges.segments.push_back(intervals.edges.segments[k]);
    out.edges.channel.push_back(intervals.edges.channel[k]);
    out.edges.polygon.push_back(intervals.edges.polygon[k]);
    out.edges.next.push_back(base + k);
    out.edges.weight.push_back(intervals.edges.weight[k]);
    out.unchained.push_back(1);
  }
  return out;
}

}  // namespace edgeland::detail
