// build_plane_graph, step 2: vertex ids (plane_graph_build.hpp).
//
// A piece (fragment of a touched segment) ends where the next one along its ring starts: the
// next fragment of its segment, or the first piece or chain of the next segment (snap rounding
// never moves an input vertex, so a segment's fragments run from its start to its end). So the
// starts of pieces and chains are all the vertex occurrences, and sorting them once by key both
// numbers the vertices and gives every piece and chain its end ids, with half the keys of
// sorting both ends and no search.
#include <algorithm>

#include "edgeland/kernel/assert.hpp"
#include "offsets.hpp"
#include "plane_graph_build.hpp"
#include "point_key.hpp"
#include "radix_sort.hpp"

namespace edgeland::detail::plane_graph_build {
namespace {

constexpr const char* kStage = "plane graph";

// A point as one 64-bit key with the same (lexicographic) order: every coordinate is within
// kCoordBound = 2^31 - 1 (inputs are validated; snapped points round crossings of in-range
// segments, and lie between their ends), so c + 2^31 fits in 32 bits. Sorting and searching
// keys is several times faster than comparing points.
std::uint64_t key_of(Point64 p) {
  if (!in_range(p)) fail_stage(kStage, "vertex out of range");
  return point_key(p);
}

// Where a vertex occurs: the start of a chain or piece, or an open end.
struct Start {
  std::uint64_t key;
  std::uint32_t occurrence;  // index into VertexNumbering::vertex_of
};

// Every occurrence, in order: chain starts, then piece starts (piece i is occurrence
// piece_base + i), then open ends. Fills first_occurrence, own_end and the pieces' tags.
class Occurrences {
 public:
  Occurrences(const EdgeList& edges, VertexNumbering& out) : edges_(edges), out_(out) {}

  void add_chain_starts(const ChainPlan& plan) {
    for (const PlaneGraph::Chain& c : plan.chains) {
      out_.first_occurrence[c.first] = next_id();
      add(edges_.segments[c.first].a);
    }
  }
  // Written by index (sized once): this runs once per fragment.
  void add_piece_starts(const std::vector<Fragment>& fragments, const FragmentRanges& ranges,
                        const ChainPlan& plan);
  // Segments that are not in rings (hole splitting's pieces) end where nothing starts.
  void add_open_ends(const ChainPlan& plan) {
    const auto& segs = edges_.segments;
    for (const std::uint32_t s : plan.touched) {
      if (segs[edges_.next[s]].a == segs[s].b) continue;
      if (out_.own_end.empty()) out_.own_end.assign(edges_.size(), kNoOccurrence);
      out_.own_end[s] = next_id();
      add(segs[s].b);
    }
  }
  std::vector<Start>& starts() { return starts_; }

 private:
  std::uint32_t next_id() const { return static_cast<std::uint32_t>(starts_.size()); }
  void add(Point64 p) { starts_.push_back({key_of(p), next_id()}); }
  void add_pieces_of(std::uint32_t s, const std::vector<Fragment>& fragments,
                     const FragmentRanges& ranges, std::uint32_t& at);

  const EdgeList& edges_;
  VertexNumbering& out_;
  std::uint32_t piece_base_ = 0;  // piece i is occurrence piece_base_ + i
  ScratchVector<Start> starts_;
};

void Occurrences::add_piece_starts(const std::vector<Fragment>& fragments,
                                   const FragmentRanges& ranges, const ChainPlan& plan) {
  std::size_t count = 0;
  for (const std::uint32_t s : plan.touched) count += ranges.piece_count(s);
  starts_.reserve(starts_.size() + count + plan.touched.size());
  piece_base_ = next_id();
  std::uint32_t at = piece_base_;
  starts_.resize(starts_.size() + count);
  out_.pieces.resize(count);
  for (const std::uint32_t s : plan.touched) add_pieces_of(s, fragments, ranges, at);
}

// The pieces of segment s, from occurrence `at` on. The direction (sign) of each is set once
// the end ids are known.
void Occurrences::add_pieces_of(std::uint32_t s, const std::vector<Fragment>& fragments,
                                const FragmentRanges& ranges, std::uint32_t& at) {
  out_.first_occurrence[s] = at;
  auto add_piece = [&](Point64 start) {
    starts_[at] = {key_of(start), at};
    out_.pieces[at - piece_base_] = {0, 0, edges_.polygon[s], edges_.channel[s], 0};
    ++at;
  };
  if (!ranges.listed(s)) return add_piece(edges_.segments[s].a);  // its own single piece
  Point64 expected = edges_.segments[s].a;
  for (std::uint32_t k = ranges.first(s); k < ranges.last(s); ++k) {
    const Segment& f = fragments[k].seg;
    // Not reached by tests: snap rounding's fragments run end to end.
    if (f.a != expected) fail_stage(kStage, "the fragments of a segment do not run end to end");
    expected = f.b;
    add_piece(f.a);
  }
  if (expected != edges_.segments[s].b)  // Not reached by tests (as above).
    fail_stage(kStage, "the fragments of a segment do not run end to end");
}

// Vertex ids from the sorted starts: one per distinct key.
void number_sorted(const std::vector<Start>& starts, VertexNumbering& out) {
  out.keys.clear();
  out.keys.reserve(starts.size());
  out.vertex_of.resize(starts.size());
  for (const Start& st : starts) {
    if (out.keys.empty() || out.keys.back() != st.key) out.keys.push_back(st.key);
    out.vertex_of[st.occurrence] = static_cast<std::uint32_t>(out.keys.size() - 1);
  }
}

// Each piece's end ids and direction: it ends where the next piece of its segment starts, or,
// for the last, where the segment ends.
void orient_pieces(const EdgeList& edges, const FragmentRanges& ranges, const ChainPlan& plan,
                   std::uint32_t piece_base, VertexNumbering& out) {
  std::uint32_t i = 0;
  for (const std::uint32_t s : plan.touched) {
    const std::uint32_t count = ranges.piece_count(s);
    const std::int32_t weight = edges.weight_of(s);
    for (std::uint32_t k = 0; k < count; ++k, ++i) {
      const std::uint32_t a = out.vertex_of[piece_base + i];
      const std::uint32_t b =
          k + 1 == count ? out.end_vertex(s, edges.next) : out.vertex_of[piece_base + i + 1];
      FragmentEdge& piece = out.pieces[i];
      piece.net = a < b ? weight : -weight;
      piece.lo = std::min(a, b);
      piece.hi = std::max(a, b);
    }
  }
}

}  // namespace

FragmentRanges::FragmentRanges(const std::vector<Fragment>& fragments,
                               std::uint32_t segment_count) {
  first_.assign(segment_count + 1, 0);
  for (const Fragment& f : fragments) ++first_[f.parent + 1];
  add_up_counts(first_);
}

std::uint32_t VertexNumbering::end_vertex(std::uint32_t s,
                                          const std::vector<std::uint32_t>& next) const {
  const std::uint32_t o =
      own_end.empty() || own_end[s] == kNoOccurrence ? first_occurrence[next[s]] : own_end[s];
  if (o == kNoOccurrence) fail_stage(kStage, "a segment ends inside a chain");
  return vertex_of[o];
}

void number_vertices(const EdgeList& edges, const std::vector<Fragment>& fragments,
                     const FragmentRanges& ranges, const ChainPlan& plan, VertexNumbering& out) {
  out.first_occurrence.assign(edges.size(), kNoOccurrence);
  out.own_end.clear();
  Occurrences occurrences(edges, out);
  occurrences.add_chain_starts(plan);
  const auto piece_base = static_cast<std::uint32_t>(occurrences.starts().size());
  occurrences.add_piece_starts(fragments, ranges, plan);
  occurrences.add_open_ends(plan);
  radix_sort(occurrences.starts(), [](const Start& x) { return x.key; });
  number_sorted(occurrences.starts(), out);
  orient_pieces(edges, ranges, plan, piece_base, out);
}

}  // namespace edgeland::detail::plane_graph_build
