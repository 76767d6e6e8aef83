// check_fragments (stage_checks.hpp): snap rounding's promises to the plane graph.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "candidate_pairs.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "stage_check_text.hpp"
#include "stage_checks.hpp"

namespace edgeland::detail {
namespace {

constexpr const char* kStage = "snap rounding";
constexpr std::uint32_t kUnlisted = 0xffffffffu;

std::string num(std::size_t i) { return std::to_string(i); }

void check_sizes(const EdgeList& edges, const std::vector<std::uint8_t>& touched) {
  const std::size_t n = edges.size();
  if (touched.size() != n || edges.next.size() != n)
    fail_stage(kStage, "sizes: " + num(n) + " segments, " + num(touched.size()) +
                           " touched flags, " + num(edges.next.size()) + " ring links");
  for (std::size_t s = 0; s < n; ++s) {
    if (edges.next[s] >= n)
      fail_stage(kStage, "sizes: segment " + num(s) + " links to segment " + num(edges.next[s]) +
                             " of " + num(n));
    if (edges.segments[s].a == edges.segments[s].b)  // edge collection skips repeated points
      fail_stage(kStage,
                 "zero-length fragment: segment " + num(s) + " at " + text(edges.segments[s].a));
  }
}

// Fragment k starts where the one before it ends, or at its segment's start; the last one of
// its segment ends at the segment's end.
void check_end_to_end(const EdgeList& edges, const std::vector<Fragment>& fragments,
                      std::size_t k) {
  const Fragment& f = fragments[k];
  const Segment& seg = edges.segments[f.parent];
  const bool first = k == 0 || fragments[k - 1].parent != f.parent;
  const Point64 start = first ? seg.a : fragments[k - 1].seg.b;
  if (f.seg.a != start)
    fail_stage(kStage, "end to end: fragment " + num(k) + " of segment " + num(f.parent) +
                           " starts at " + text(f.seg.a) + ", not at " + text(start) +
                           (first ? " (its segment's start)" : " (the previous fragment's end)"));
  const bool last = k + 1 == fragments.size() || fragments[k + 1].parent != f.parent;
  if (last && f.seg.b != seg.b)
    fail_stage(kStage, "end to end: fragment " + num(k) + " of segment " + num(f.parent) +
                           " ends at " + text(f.seg.b) + ", not at its segment's end " +
                           text(seg.b));
}

void check_listed(const EdgeList& edges, const std::vector<Fragment>& fragments,
                  const std::vector<std::uint8_t>& touched) {
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    const Fragment& f = fragments[k];
    if (f.seg.a == f.seg.b)
      fail_stage(kStage, "zero-length fragment: fragment " + num(k) + " at " + text(f.seg.a));
    if (f.parent >= edges.size())
      fail_stage(kStage, "parent out of range: fragment " + num(k) + " names segment " +
                             num(f.parent) + " of " + num(edges.size()));
    const Segment& seg = edges.segments[f.parent];
    for (const Point64 end : {f.seg.a, f.seg.b})
      if (!segment_meets_closed_pixel(seg, end))
        fail_stage(kStage, "strays from its segment: fragment " + num(k) + " of segment " +
                               num(f.parent) + " " + text(seg) + " ends at " + text(end) +
                               ", more than half a unit from it");
    if (k > 0 && f.parent < fragments[k - 1].parent)
      fail_stage(kStage, "parent order: fragment " + num(k) + " (segment " + num(f.parent) +
                             ") follows fragment " + num(k - 1) + " (segment " +
                             num(fragments[k - 1].parent) + ")");
    if (!touched[f.parent])
      fail_stage(kStage, "listed but untouched: fragment " + num(k) + " of untouched segment " +
                             num(f.parent));
  }
  // Second: a fragment's end is compared with its successor's parent.
  for (std::size_t k = 0; k < fragments.size(); ++k) check_end_to_end(edges, fragments, k);
}

// An untouched segment is chained on into its ring successor: it must end where that starts.
void check_untouched_ends(const EdgeList& edges, const std::vector<std::uint8_t>& touched) {
  for (std::size_t s = 0; s < edges.size(); ++s) {
    if (touched[s]) continue;
    const Point64 end = edges.segments[s].b, next_start = edges.segments[edges.next[s]].a;
    if (end != next_start)
      fail_stage(kStage, "untouched end: untouched segment " + num(s) + " ends at " + text(end) +
                             " but its ring successor " + num(edges.next[s]) + " starts at " +
                             text(next_start));
  }
}

// Every fragment in segment order: the listed ones, and each segment without any as itself.
// link[i] is i + 1 when fragment i + 1 continues fragment i along its ring from its end, and i
// otherwise: what SegmentIndex reads as ring links to form monotone runs.
struct AllFragments {
  std::vector<Segment> seg;
  std::vector<std::uint32_t> parent, listed, link;  // listed: index in `fragments`, or kUnlisted
};

void add_fragment(AllFragments& all, const Segment& s, std::uint32_t parent, std::uint32_t listed) {
  all.seg.push_back(s);
  all.parent.push_back(parent);
  all.listed.push_back(listed);
}

AllFragments all_fragments(const EdgeList& edges, const std::vector<Fragment>& fragments) {
  AllFragments all;
  const auto n = static_cast<std::uint32_t>(edges.size());
  for (std::uint32_t s = 0, k = 0; s < n; ++s) {
    if (k == fragments.size() || fragments[k].parent != s)
      add_fragment(all, edges.segments[s], s, kUnlisted);
    for (; k < fragments.size() && fragments[k].parent == s; ++k)
      add_fragment(all, fragments[k].seg, s, k);
  }
  const auto m = static_cast<std::uint32_t>(all.seg.size());
  all.link.resize(m);
  for (std::uint32_t i = 0; i < m; ++i) {
    const bool along_ring = i + 1 < m && (all.parent[i + 1] == all.parent[i] ||
                                          all.parent[i + 1] == edges.next[all.parent[i]]);
    all.link[i] = along_ring && all.seg[i].b == all.seg[i + 1].a ? i + 1 : i;
  }
  return all;
}

enum class Contact : std::uint8_t {
  kApart,
  kSharedEnd,
  kSame,
  kCrossing,
  kEndInside,
  kPartialOverlap
};

// How two fragments meet, exactly (kernel predicates only).
Contact contact_of(const Segment& s, const Segment& t) {
  if ((s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a)) return Contact::kSame;
  if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) {
    const Point64 p = (s.a == t.a || s.a == t.b) ? s.a : s.b;
    const Point64 s_far = s.a == p ? s.b : s.a, t_far = t.a == p ? t.b : t.a;
    // Two segments from one point meet again only when they run along one ray from it.
    const bool along =
        orientation(p, s_far, t_far) == Orientation::kCollinear && dot_sign(p, s_far, t_far) > 0;
    return along ? Contact::kPartialOverlap : Contact::kSharedEnd;
  }
  switch (intersect(s, t).relation) {
    case SegmentRelation::kDisjoint:
      return Contact::kApart;
    case SegmentRelation::kCrossing:
      return Contact::kCrossing;
    case SegmentRelation::kTouching:
      return Contact::kEndInside;  // no end is shared
    case SegmentRelation::kOverlapping:
      return Contact::kPartialOverlap;
  }
  return Contact::kCrossing;  // Not reached: the switch covers every relation.
}

std::string describe(const AllFragments& all, std::uint32_t i) {
  const std::string where = text(all.seg[i]);
  if (all.listed[i] == kUnlisted) return "segment " + num(all.parent[i]) + " " + where;
  return "fragment " + num(all.listed[i]) + " (segment " + num(all.parent[i]) + ") " + where;
}

// Whether fragment j of an untouched segment's ring neighbour meets the untouched segment
// (fragment i, itself) only at their common end along the ring.
bool meets_as_ring_neighbour(const EdgeList& edges, const AllFragments& all, std::uint32_t i,
                             std::uint32_t j) {
  const std::uint32_t s = all.parent[i], t = all.parent[j];
  const Segment &fs = all.seg[i], &ft = all.seg[j];
  return (edges.next[s] == t && fs.b == ft.a) || (edges.next[t] == s && fs.a == ft.b);
}

void check_pair(const EdgeList& edges, const std::vector<std::uint8_t>& touched,
                const AllFragments& all, std::uint32_t i, std::uint32_t j) {
  const Contact c = contact_of(all.seg[i], all.seg[j]);
  if (c == Contact::kApart) return;
  auto pair = [&] { return describe(all, i) + " and " + describe(all, j); };  // on failure only
  if (c == Contact::kCrossing) fail_stage(kStage, "crossing: " + pair() + " cross properly");
  if (c == Contact::kEndInside)
    fail_stage(kStage, "endpoint inside: " + pair() + " meet at an end of one inside the other");
  if (c == Contact::kPartialOverlap)
    fail_stage(kStage,
               "partial overlap: " + pair() + " share a stretch but are not the same segment");
  for (const auto& [x, y] : {std::pair{i, j}, std::pair{j, i}})
    if (!touched[all.parent[x]] &&
        (c == Contact::kSame || !meets_as_ring_neighbour(edges, all, x, y)))
      fail_stage(kStage, "untouched contact: " + pair() + " meet, but segment " +
                             num(all.parent[x]) + " is untouched");
}

// Every pair of segments whose closed boxes overlap, except consecutive segments of one
// monotone run (they meet only at their common end), found as noding finds them
// (candidate_pairs.hpp), so this costs what noding costs on as many segments.
template <class F>
void for_each_box_pair(const std::vector<Segment>& segs, const std::vector<std::uint32_t>& link,
                       F&& visit) {
  const SegmentIndex index(segs, link);
  std::unique_ptr<SegmentGrid> grid;
  if (runs_are_short(index, segs.size())) grid = std::make_unique<SegmentGrid>(segs);
  if (grid != nullptr) {
    const std::string why = grid->offsets_violation(segs);
    if (!why.empty()) fail_stage(kStage, "segment grid: " + why);
  }
  for_each_candidate_pair(segs, index, grid.get(), false, nullptr, visit);
}

}  // namespace

void check_fragments(const EdgeList& edges, const std::vector<Fragment>& fragments,
                     const std::vector<std::uint8_t>& touched) {
  check_sizes(edges, touched);
  check_listed(edges, fragments, touched);
  check_untouched_ends(edges, touched);
  const AllFragments all = all_fragments(edges, fragments);
  for_each_box_pair(all.seg, all.link, [&](std::uint32_t i, std::uint32_t j) {
    check_pair(edges, touched, all, i, j);
  });
}

}  // namespace edgeland::detail
