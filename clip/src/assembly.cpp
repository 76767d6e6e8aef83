#include "assembly.hpp"

#include <algorithm>

#include "canonical.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

std::vector<std::vector<std::uint32_t>> split_at_repeated_vertices(
    const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last,
    std::vector<std::int32_t>& position) {
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<std::uint32_t> stack;  // half-edges; position[v]: index of the one leaving v
  for (const std::uint32_t* it = first; it != last; ++it) {
    const std::uint32_t h = *it;
    const std::uint32_t v = g.origin(h);
    if (position[v] >= 0) {
      // v closes a loop: every half-edge pushed since v was first left.
      const std::size_t start = static_cast<std::size_t>(position[v]);
      loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(start), stack.end());
      for (std::size_t i = start; i < stack.size(); ++i) position[g.origin(stack[i])] = -1;
      stack.resize(start);
    }
    position[v] = static_cast<std::int32_t>(stack.size());
    stack.push_back(h);
  }
  for (std::uint32_t h : stack) position[g.origin(h)] = -1;
  if (!stack.empty()) loops.push_back(std::move(stack));
  return loops;
}

Ring ring_along(const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last) {
  Ring ring;
  ring_along_into(g, first, last, ring);
  return ring;
}

void ring_along_into(const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last,
                     std::vector<Point64>& ring) {
  std::size_t points = 0;
  for (const std::uint32_t* h = first; h != last; ++h) points += 1 + g.interior_count(*h >> 1);
  ring.clear();
  ring.reserve(points);
  for (const std::uint32_t* h = first; h != last; ++h) g.append_points(*h, ring);
}

namespace {

// The half-edge after `cur` along the boundary of its region (label): the sharpest left turn.
// From the reversed edge, turn clockwise to the first edge that bounds the same region.
// turn_at[x] locates the half-edge clockwise after x's twin, so the candidate after h round the
// same vertex is at turn_at[h ^ 1]; the vertex's degree bounds the search. Returns cur when
// there is none.
std::uint32_t next_on_boundary(const PlaneGraph& g, const std::vector<FaceLabel>& emitted,
                               std::uint32_t cur, FaceLabel label) {
  std::uint32_t next = g.around[g.turn_at[cur]];
  const std::uint32_t w = g.target(cur), degree = g.around_begin[w + 1] - g.around_begin[w];
  for (std::uint32_t tried = 1; emitted[next] != label; ++tried) {
    // Not reached by tests: a region's boundary always continues at its vertex.
    if (tried >= degree) return cur;
    next = g.around[g.turn_at[next ^ 1]];
  }
  return next;
}

}  // namespace

BoundaryWalks trace_boundaries(const PlaneGraph& g, const std::vector<FaceLabel>& emitted) {
  const std::size_t nh = emitted.size();
  BoundaryWalks walks;
  walks.begin.push_back(0);
  walks.half_edges.reserve(nh);  // each half-edge is walked at most once
  ScratchVector<std::uint8_t> used;
  used.assign(nh, false);
  // left_in[v]: 1 + the walk that last left vertex v (0: none yet), to see a walk revisit one.
  ScratchVector<std::uint32_t> left_in;
  left_in.assign(g.vertices.size(), 0);
  for (std::uint32_t start = 0; start < nh; ++start) {
    const FaceLabel label = emitted[start];
    if (label < 0 || used[start]) continue;
    const auto walk = static_cast<std::uint32_t>(walks.label.size() + 1);
    std::uint8_t revisits = 0;
    for (std::uint32_t cur = start, next;; cur = next) {
      used[cur] = true;
      walks.half_edges.push_back(cur);
      std::uint32_t& left_by = left_in[g.origin(cur)];
      revisits |= static_cast<std::uint8_t>(left_by == walk);
      left_by = walk;
      next = next_on_boundary(g, emitted, cur, label);
      if (next == cur || (used[next] && next != start))  // Not reached by tests: an internal error.
        fail_stage("assembly", "region boundary does not close");
      if (next == start) break;
    }
    walks.label.push_back(label);
    walks.revisits.push_back(revisits);
    walks.begin.push_back(static_cast<std::uint32_t>(walks.half_edges.size()));
  }
  return walks;
}

namespace {

// The points where two rings of one region touch, sorted (a point appears in several rings).
ScratchVector<Point64> shared_points(const RegionRings& region) {
  ScratchVector<Point64> all;
  for (const auto* rings : {&region.outers, &region.holes})
    for (const Ring& r : *rings) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end());
  ScratchVector<Point64> shared;
  for (std::size_t i = 1; i < all.size(); ++i)
    if (all[i] == all[i - 1] && (shared.empty() || shared.back() != all[i]))
      shared.push_back(all[i]);
  return shared;
}

// A region's rings reduced to its corners and shared points (Assembled, corner_bridges).
void keep_corners_and_shared_points(RegionRings& region) {
  const ScratchVector<Point64> shared = shared_points(region);
  for (auto* rings : {&region.outers, &region.holes})
    for (Ring& r : *rings) drop_collinear_except(r, shared);
}

}  // namespace

namespace {

// emitted[h]: the label of the result region on the left of half-edge h, where the edge
// separates two different labels (-1 elsewhere: not on any region's boundary).
void label_boundary_half_edges(const PlaneGraph& g, const std::vector<SideState>& left,
                               const LabelOf& label_of, std::vector<FaceLabel>& emitted) {
  emitted.assign(2 * g.edge_count(), -1);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const FaceLabel l = label_of(left[2 * e]), r = label_of(left[2 * e + 1]);
    if (l == r) continue;
    emitted[2 * e] = l;
    emitted[2 * e + 1] = r;
  }
}

// Where a ring's half-edges are kept, to trace it again for hole splitting: its walk's stretch
// of half-edges, or for a loop split off a walk, a copy.
struct LoopSpan {
  std::uint32_t begin, end;  // in the walks' half-edges, or in split_loops when `split`
  bool split;
};

// The loops of the boundary walks, each written out in canonical form at once
// (canonical.hpp): it starts at its smallest point, which is a graph vertex (no chain has an
// interior point smaller than both its ends), and the turn there is its orientation, so
// neither a pass for the area nor one to rotate is needed. Collinear points can only be graph
// vertices, or chain points when an operand ring had collinear consecutive vertices.
class RingWriter {
 public:
  RingWriter(const PlaneGraph& g, bool collinear_free_operands, std::size_t walks)
      : g_(g), check_chains_(collinear_free_operands ? 0 : 1) {
    ring_begin_.reserve(walks + 1);
    ring_begin_.push_back(0);
    ring_label.reserve(walks);
    outer.reserve(walks);
  }
  // Adds the loop [first, last) of half-edges; false when it encloses no area.
  bool add_loop(FaceLabel label, const std::uint32_t* first, const std::uint32_t* last);
  std::size_t size() const { return ring_label.size(); }
  // Ring i as an output polygon (allocated once, at its size).
  Ring ring(std::size_t i) const {
    return Ring(ring_points_.begin() + ring_begin_[i], ring_points_.begin() + ring_begin_[i + 1]);
  }

  ScratchVector<FaceLabel> ring_label;  // of ring i
  ScratchVector<std::uint8_t> outer;    // ring i turns counter-clockwise
  std::size_t holes = 0;

 private:
  std::size_t gather_points(const std::uint32_t* first, const std::uint32_t* last, bool& chains);

  const PlaneGraph& g_;
  const std::uint8_t check_chains_;
  ScratchVector<Point64> points_;
  ScratchVector<std::uint8_t> check_;  // which points may be dropped
  // The canonical rings written, flat: ring i is ring_points_[ring_begin_[i] .. [i + 1]). Only
  // the rings of labels without holes become output polygons; the rest are traced again.
  ScratchVector<Point64> ring_, ring_points_;
  ScratchVector<std::uint32_t> ring_begin_;
};

// The loop's points into points_, with check_ marking those canonical_ring_from tests for
// collinearity (every vertex; chain points only when operands may have collinear vertices).
// Returns the position of the least point; `chains`: whether chain points are among them.
std::size_t RingWriter::gather_points(const std::uint32_t* first, const std::uint32_t* last,
                                      bool& chains) {
  points_.clear();
  check_.clear();
  std::size_t least = 0;
  chains = false;
  for (const std::uint32_t* h = first; h != last; ++h) {
    const std::size_t at = points_.size();
    g_.append_points(*h, points_);
    if (points_[at] < points_[least]) least = at;
    if (points_.size() == at + 1) {  // a vertex alone
      if (chains) check_.push_back(1);
      continue;
    }
    // Marks are written from the first chain on: every point before it is a vertex.
    if (!chains) check_.assign(at, 1);
    chains = true;
    check_.push_back(1);
    check_.resize(points_.size(), check_chains_);
  }
  return least;
}

bool RingWriter::add_loop(FaceLabel label, const std::uint32_t* first, const std::uint32_t* last) {
  bool chains = false;
  const std::size_t least = gather_points(first, last, chains);
  int turn = 0;
  // Without chain points every point is a graph vertex, each one tested.
  canonical_ring_into(points_, chains ? check_.data() : nullptr, least, turn, ring_);
  if (turn == 0) {
    // Not expected of a face boundary (simple, so nonzero area means a convex smallest
    // vertex); decided by the area as before, should it happen. Not reached by tests.
    const Int128 area = points_.size() < 3 ? 0 : twice_signed_area(points_);
    if (area == 0) return false;
    const Ring r = canonical_ring(Ring(points_.begin(), points_.end()));
    ring_.assign(r.begin(), r.end());
    turn = area > 0 ? 1 : -1;
  }
  ring_points_.insert(ring_points_.end(), ring_.begin(), ring_.end());
  ring_begin_.push_back(static_cast<std::uint32_t>(ring_points_.size()));
  ring_label.push_back(label);
  outer.push_back(turn > 0);
  if (turn < 0) ++holes;
  return true;
}

// Every walk's loops written out; a walk that revisits a vertex is split there first. The
// half-edges of each ring written are recorded in `loops` (and split_loops).
void write_loops(const PlaneGraph& g, const BoundaryWalks& walks, RingWriter& writer,
                 std::vector<LoopSpan>& loops, std::vector<std::uint32_t>& split_loops) {
  ScratchVector<std::int32_t> position;  // split_at_repeated_vertices
  for (std::size_t w = 0; w < walks.size(); ++w) {
    const std::uint32_t *first = walks.first(w), *last = walks.last(w);
    // Most walks visit every vertex once: then the walk is the loop, with nothing to split.
    if (!walks.revisits[w]) {
      if (writer.add_loop(walks.label[w], first, last))
        loops.push_back({walks.begin[w], walks.begin[w + 1], false});
      continue;
    }
    if (position.empty()) position.assign(g.vertices.size(), -1);
    for (const auto& loop : split_at_repeated_vertices(g, first, last, position)) {
      if (!writer.add_loop(walks.label[w], loop.data(), loop.data() + loop.size())) continue;
      const auto from = static_cast<std::uint32_t>(split_loops.size());
      split_loops.insert(split_loops.end(), loop.begin(), loop.end());
      loops.push_back({from, static_cast<std::uint32_t>(split_loops.size()), true});
    }
  }
}

// The rings written, grouped by label when some label has holes: regions with holes move to
// out.holed (traced again along their half-edges, every graph vertex kept); the rest stay, in
// their order.
class RegionSorter {
 public:
  RegionSorter(const PlaneGraph& g, const BoundaryWalks& walks, const std::vector<LoopSpan>& loops,
               const std::vector<std::uint32_t>& split_loops, const RingWriter& writer)
      : g_(g), walks_(walks), loops_(loops), split_loops_(split_loops), writer_(writer) {}

  void run(bool corner_bridges, Assembled& out) const;

 private:
  void trace(std::uint32_t r, std::vector<Point64>& ring) const {
    const LoopSpan& l = loops_[r];
    const std::uint32_t* base = l.split ? split_loops_.data() : walks_.half_edges.data();
    ring_along_into(g_, base + l.begin, base + l.end, ring);
  }

  const PlaneGraph& g_;
  const BoundaryWalks& walks_;
  const std::vector<LoopSpan>& loops_;
  const std::vector<std::uint32_t>& split_loops_;
  const RingWriter& writer_;
};

void RegionSorter::run(bool corner_bridges, Assembled& out) const {
  const auto& label = writer_.ring_label;
  ScratchVector<std::uint32_t> order;
  order.resize(writer_.size());
  out.rings.reserve(writer_.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  // By label, in their order within one (std::sort with the index as tie-break: what a stable
  // sort gives, without its buffer).
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return label[x] != label[y] ? label[x] < label[y] : x < y;
  });
  for (std::size_t i = 0, j; i < order.size(); i = j) {
    bool with_holes = false;
    for (j = i; j < order.size() && label[order[j]] == label[order[i]]; ++j)
      with_holes = with_holes || !writer_.outer[order[j]];
    if (!with_holes) {
      for (std::size_t k = i; k < j; ++k) {
        out.rings.push_back(writer_.ring(order[k]));
        out.labels.push_back(label[order[k]]);
      }
      continue;
    }
    RegionRings& region = out.holed.emplace_back();
    region.label = label[order[i]];
    for (std::size_t k = i; k < j; ++k)
      trace(order[k], (writer_.outer[order[k]] ? region.outers : region.holes).emplace_back());
    if (corner_bridges) keep_corners_and_shared_points(region);
  }
}

}  // namespace

// Rings are collected flat with their label. Only when there are holes are they grouped by
// label (in increasing order, what a map from label to region would give): most results have
// none, and then every ring is an output polygon as it stands, with no region per label.
Assembled assemble(const PlaneGraph& g, const std::vector<SideState>& left, const LabelOf& label_of,
                   bool collinear_free_operands, bool corner_bridges) {
  ScratchVector<FaceLabel> emitted;
  label_boundary_half_edges(g, left, label_of, emitted);
  const BoundaryWalks walks = trace_boundaries(g, emitted);
  Assembled out;
  RingWriter writer(g, collinear_free_operands, walks.size());
  ScratchVector<LoopSpan> loops;  // one per ring written
  ScratchVector<std::uint32_t> split_loops;
  write_loops(g, walks, writer, loops, split_loops);
  if (writer.holes == 0) {
    out.rings.reserve(writer.size());
    for (std::size_t i = 0; i < writer.size(); ++i) out.rings.push_back(writer.ring(i));
    out.labels.swap(writer.ring_label);
    return out;
  }
  RegionSorter(g, walks, loops, split_loops, writer).run(corner_bridges, out);
  return out;
}

}  // namespace edgeland::detail
