// Noding of a small edge list (small_overlay.hpp): ring pairs whose boxes meet, then the
// segments of each that reach the other's box, then the pairs whose boxes meet, classified
// exactly by noding's classify_pair. A landscape cell's overlay has a few rings (the regions in
// play, the shape's members, the window) of which most pairs are apart or meet in a handful of
// segments; most of a large shape's segments never reach the cell's rings.
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "small_overlay.hpp"

namespace edgeland::detail {
namespace {

// The rings of an edge list (consecutive segments, the last one's `next` the first) with their
// boxes, and every segment's box. One per thread, kept between calls.
struct RingBoxes {
  std::vector<std::uint32_t> begin;  // ring r: segments [begin[r], begin[r + 1])
  std::vector<Box64> ring_box;
  std::vector<Box64> segment_box;
  std::vector<std::uint32_t> reaching;  // scratch: one ring's segments reaching another's box
};

RingBoxes& ring_boxes() {
  thread_local RingBoxes w;
  return w;
}

void find_rings(const EdgeList& edges, RingBoxes& w) {
  const std::size_t n = edges.size();
  w.begin.clear();
  w.ring_box.clear();
  w.segment_box.resize(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    const Box64 b = segment_box(edges.segments[s]);
    w.segment_box[s] = b;
    if (s == 0 || edges.next[s - 1] != s) {
      w.begin.push_back(s);
      w.ring_box.push_back(b);
    } else {
      w.ring_box.back().expand(b);
    }
  }
  w.begin.push_back(static_cast<std::uint32_t>(n));
}

// Classifies pair (i, j) of different rings into `c`; any meeting touches both (they are no
// ring neighbours, so even a shared end counts).
void visit_pair(const EdgeList& edges, std::uint32_t i, std::uint32_t j, Contacts& c) {
  if (classify_pair(edges.segments[i], i, edges.segments[j], j, c) == Meeting::kNone) return;
  c.touched[i] = c.touched[j] = true;
}

// The pairs between rings a and b whose closed boxes overlap.
void pairs_between(const EdgeList& edges, std::uint32_t a, std::uint32_t b, RingBoxes& w,
                   Contacts& c) {
  w.reaching.clear();
  for (std::uint32_t j = w.begin[b]; j < w.begin[b + 1]; ++j)
    if (w.segment_box[j].overlaps(w.ring_box[a])) w.reaching.push_back(j);
  if (w.reaching.empty()) return;
  for (std::uint32_t i = w.begin[a]; i < w.begin[a + 1]; ++i) {
    const Box64& bi = w.segment_box[i];
    if (!bi.overlaps(w.ring_box[b])) continue;
    for (std::uint32_t j : w.reaching)
      if (bi.overlaps(w.segment_box[j])) visit_pair(edges, i, j, c);
  }
}

}  // namespace

Contacts find_contacts_small(const EdgeList& edges) {
  Contacts c;
  c.touched.assign(edges.size(), false);
  RingBoxes& w = ring_boxes();
  find_rings(edges, w);
  const auto rings = static_cast<std::uint32_t>(w.ring_box.size());
  for (std::uint32_t a = 0; a < rings; ++a)
    for (std::uint32_t b = a + 1; b < rings; ++b)
      if (w.ring_box[a].overlaps(w.ring_box[b])) pairs_between(edges, a, b, w, c);
  return c;
}

}  // namespace edgeland::detail
