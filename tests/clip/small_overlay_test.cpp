// Stage test of the small overlay's noding and snap rounding (clip/src/small_overlay.hpp): on
// the operand pairs of the differential properties (slivers, shared and reverse-shared edges,
// vertices on edges, fans, coordinates at the ends of the range) with a window ring, as a
// labeled overlay arranges them, they hand the plane graph what the general find_contacts()
// and snap_round() hand it: the same fragments, hot pixels and moved boxes; touched flags may
// only be added (a segment found meeting another at a shared end keeps out of a chain).
#include "small_overlay.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "generators.hpp"
#include "segment_search.hpp"

namespace edgeland::detail {
namespace {

// The pair as a labeled overlay arranges it: the first operand's polygons (channel 0), the
// second's and a window ring around both (channel 1) when asked.
EdgeList overlay_edges(const test::OperandPair& p, bool window) {
  EdgeList edges;
  append_ring_edges(p.a, kSubjectChannel, true, edges);
  append_ring_edges(p.b, kClipChannel, true, edges);
  if (window) {
    Box64 box = bounding_box(p.a).value_or(Box64{{0, 0}, {1, 1}});
    if (const auto b = bounding_box(p.b)) box.expand(*b);
    const std::int64_t cut = (box.max.x - box.min.x) / 3;  // through both, not around
    box.max.x -= cut;
    if (box.has_interior() && in_range(box.min) && in_range(box.max))
      append_box_edges(box, kClipChannel, 0, edges);
  }
  return edges;
}

struct General {
  Contacts contacts;
  Snapped snapped;
};

General general(const EdgeList& edges) {
  SegmentSearch search(edges.segments, edges.next);
  General g{find_contacts(edges.segments, edges.next, search, {true}), {}};
  g.snapped = snap_round(edges.segments, edges.next, g.contacts, search);
  return g;
}

bool same_fragments(const std::vector<Fragment>& a, const std::vector<Fragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].seg != b[i].seg || a[i].parent != b[i].parent) return false;
  return true;
}

RC_GTEST_PROP(SmallOverlay, NodesAndSnapRoundsAsTheGeneralPipeline, ()) {
  const test::OperandPair pair = *test::gen::operand_pair();
  const EdgeList edges = overlay_edges(pair, *rc::gen::arbitrary<bool>());
  const General expected = general(edges);
  Contacts contacts = find_contacts_small(edges);
  RC_ASSERT(contacts.intersections == expected.contacts.intersections);
  Snapped snapped;
  const bool taken = snap_round_small(edges, contacts, snapped);
  RC_TAG(pair.scenario, expected.snapped.hot_pixels == 0 ? "no hot pixel" : "hot pixels",
         taken ? "small" : "left to the general one");
  if (!taken) return;
  RC_ASSERT(snapped.hot_pixels == expected.snapped.hot_pixels);
  RC_ASSERT(same_fragments(snapped.fragments, expected.snapped.fragments));
  RC_ASSERT(
      std::vector<Box64>(snapped.moved_boxes.begin(), snapped.moved_boxes.end()) ==
      std::vector<Box64>(expected.snapped.moved_boxes.begin(), expected.snapped.moved_boxes.end()));
  for (std::size_t s = 0; s < edges.size(); ++s)
    RC_ASSERT(snapped.touched[s] >= expected.snapped.touched[s]);
}

}  // namespace
}  // namespace edgeland::detail
