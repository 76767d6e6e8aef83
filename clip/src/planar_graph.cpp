#include "planar_graph.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <tuple>

#include "edgeland/kernel/angle.hpp"
#include "point_key.hpp"
#include "radix_sort.hpp"
#include "edgeland/kernel/recycled_vector.hpp"

namespace edgeland::detail {
namespace {

// A point as one 64-bit key with the same (lexicographic) order: every coordinate is within
// kCoordBound = 2^31 - 1 (inputs are validated; snapped points round crossings of in-range
// segments, and lie between their ends), so c + 2^31 fits in 32 bits. Sorting and searching
// keys is several times faster than comparing points.
std::uint64_t key_of(Point64 p) {
  if (!in_range(p)) throw std::logic_error("plane graph: vertex out of range");
  return point_key(p);
}

Point64 point_of(std::uint64_t key) {
  return {static_cast<std::int64_t>(key >> 32) - kCoordBound - 1,
          static_cast<std::int64_t>(key & 0xffffffffu) - kCoordBound - 1};
}

struct Piece {
  std::uint32_t lo, hi;  // vertex ids, lo < hi
  std::int32_t polygon;
  std::uint8_t channel;
  std::int32_t net;  // the segment's weight, negated when the fragment runs hi -> lo
};

// Sorts [first, last) stably: by insertion when it is short, by merge sort otherwise. For the
// half-edges round vertices of degree above kRankedDegree (below: place_by_rank).
template <class It, class Less>
void sort_short_run(It first, It last, Less less) {
  if (last - first > 16) {
    std::stable_sort(first, last, less);
    return;
  }
  for (It i = first; i != last; ++i) {
    const auto x = *i;
    It j = i;
    for (; j != first && less(x, *(j - 1)); --j) *j = *(j - 1);
    *j = x;
  }
}

// A half-edge leaving a vertex, with the direction of its first step.
struct Out {
  Point64 d;
  std::uint32_t h;
};

// Vertices of at most this degree (most of them) get their half-edges placed by rank.
constexpr std::uint32_t kRankedDegree = 4;

// Writes the n <= kRankedDegree half-edges of one vertex (out[0 .. n), starting at position b
// of g.around) in counter-clockwise order: each one's place is the number of others before it,
// every pair compared once (a tie, which a plane graph never has, keeps the listed order), so
// the ranks are a permutation and no branch depends on a comparison: mispredicted branches
// were most of the angle sort.
void place_by_rank(const Out* out, std::uint32_t n, std::uint32_t b, PlaneGraph& g) {
  std::uint32_t rank[kRankedDegree] = {};
  for (std::uint32_t i = 1; i < n; ++i)
    for (std::uint32_t j = 0; j < i; ++j) {
      const std::uint32_t i_first = angle_less_branch_free(out[i].d, out[j].d);
      rank[j] += i_first;
      rank[i] += 1 - i_first;
    }
  for (std::uint32_t k = 0; k < n; ++k) {
    g.around[b + rank[k]] = out[k].h;
    g.turn_at[out[k].h ^ 1] = b + rank[k] - 1 + (rank[k] == 0 ? n : 0);
  }
}

}  // namespace

void PlaneGraph::append_points(std::uint32_t h, std::vector<Point64>& out) const {
  const std::uint32_t e = h >> 1, m = interior_count(e);
  out.push_back(vertices[origin(h)]);
  if (m == 0) return;
  // Walk the chain's segments in ring order, forwards or backwards as h requires.
  const Chain& c = chain[e];
  const bool forward_in_ring = ((h & 1) != 0) == c.reversed;
  // The interior points are the starts of the chain's segments 1 .. m, which lie in at most two
  // contiguous stretches of the ring (it may wrap once): copied as such, no index arithmetic
  // per point. Capacity grows geometrically: an exact-size resize per chain made glibc hand the
  // large output rings back and forth to the system (page faults, a third slower at 10^4).
  const std::vector<Segment>& segs = *segments;
  const std::uint32_t at = c.first - c.ring_begin + 1;  // ring position of segment 1
  const std::uint32_t first_part = std::min(m, c.ring_len - std::min(at, c.ring_len));
  const std::uint32_t p0 = c.ring_begin + (at < c.ring_len ? at : at - c.ring_len);
  if (out.capacity() < out.size() + m) out.reserve(std::max(out.size() + m, 2 * out.capacity()));
  if (forward_in_ring) {
    for (std::uint32_t i = 0; i < first_part; ++i) out.push_back(segs[p0 + i].a);
    for (std::uint32_t i = first_part; i < m; ++i) out.push_back(segs[c.ring_begin + (i - first_part)].a);
  } else {
    for (std::uint32_t i = m; i-- > first_part;) out.push_back(segs[c.ring_begin + (i - first_part)].a);
    for (std::uint32_t i = first_part; i-- > 0;) out.push_back(segs[p0 + i].a);
  }
}

void build_plane_graph(const EdgeList& input, const std::vector<Fragment>& fragments,
                       const std::vector<std::uint8_t>& touched, PlaneGraph& g) {
  const std::vector<Segment>& segments = input.segments;
  const std::vector<std::uint8_t>& channel_of = input.channel;
  const std::vector<std::int32_t>& polygon_of = input.polygon;
  const std::vector<std::uint32_t>& next = input.next;
  const std::uint32_t n = static_cast<std::uint32_t>(next.size());
  // Listed fragments come in segment order; a segment with none listed is its own fragment
  // (always so for an untouched one).
  RecycledVector<struct FirstFragmentBuffer, std::uint32_t> first_fragment;
  first_fragment.assign(n + 1, 0);
  for (const Fragment& f : fragments) ++first_fragment[f.parent + 1];
  for (std::uint32_t s = 0; s < n; ++s) first_fragment[s + 1] += first_fragment[s];
  auto listed = [&](std::uint32_t s) { return first_fragment[s] != first_fragment[s + 1]; };

  // Chains of untouched segments (their points are read from `segments`: an untouched segment
  // is never listed), found in one pass per ring. A chain starts after a touched segment; in a
  // ring nothing touches, at its smallest vertex and halfway round (no edge may be a loop).
  // A chain's smallest point must be one of its ends, so that every connected component's
  // smallest point is a graph vertex (labeling starts each component there, west of it). Ring
  // minima would not do: the ring's smallest vertex may belong only to pieces that cancel (a
  // spike folded back onto itself), leaving a chain's interior point the smallest. So a chain
  // whose least point is interior and below its end is cut there.
  RecycledVector<struct SpansBuffer, PlaneGraph::Chain> spans;
  RecycledVector<struct TouchedIdsBuffer, std::uint32_t> touched_ids;
  touched_ids.reserve(n);
  for (std::uint32_t b = 0; b < n;) {
    std::uint32_t e = b;
    while (next[e] == e + 1) ++e;  // the ring occupies [b, e], next[e] == b
    const std::uint32_t len = e - b + 1;
    std::size_t ring_touched = 0;
    for (std::uint32_t s = b; s <= e; ++s)
      if (touched[s]) {
        touched_ids.push_back(s);
        ++ring_touched;
      }
    auto span = [&](std::uint32_t pos, std::uint32_t segs) {  // segs segments from ring position pos
      PlaneGraph::Chain c;
      c.first = b + pos % len;
      c.count = segs - 1;
      c.ring_begin = b;
      c.ring_len = len;
      spans.push_back(c);
    };
    if (ring_touched == 0) {
      std::uint32_t smallest = 0;
      for (std::uint32_t k = 1; k < len; ++k)
        if (segments[b + k].a < segments[b + smallest].a) smallest = k;
      span(smallest, len / 2);
      span(smallest + len / 2, len - len / 2);
    } else {
      // Every gap between consecutive touched segments (cyclically) is a chain: at most two
      // contiguous ranges of ids, scanned for their least start point.
      const std::size_t t_end = touched_ids.size(), t_begin = t_end - ring_touched;
      for (std::size_t i = t_begin; i < t_end; ++i) {
        const std::uint32_t after = touched_ids[i] + 1;
        const bool wraps = i + 1 == t_end;
        const std::uint32_t upto = wraps ? e + 1 : touched_ids[i + 1];  // first range [after, upto)
        const std::uint32_t rest = wraps ? touched_ids[t_begin] - b : 0;  // then [b, b + rest)
        const std::uint32_t segs = (upto - after) + rest;
        if (segs == 0) continue;
        // Offsets in chain order; the least start point, first occurrence.
        std::uint32_t least = 0;
        Point64 least_point = segments[after < upto ? after : b].a;
        for (std::uint32_t t = after; t < upto; ++t)
          if (segments[t].a < least_point) {
            least_point = segments[t].a;
            least = t - after;
          }
        for (std::uint32_t t = b; t < b + rest; ++t)
          if (segments[t].a < least_point) {
            least_point = segments[t].a;
            least = (upto - after) + (t - b);
          }
        const std::uint32_t from = after - b;  // ring position of the chain's first segment
        const Point64 chain_end = segments[rest > 0 ? b + rest - 1 : upto - 1].b;
        if (least != 0 && least_point < chain_end) {
          span(from, least);
          span(from + least, segs - least);
        } else {
          span(from, segs);
        }
      }
    }
    b = e + 1;
  }
  // Chains in the order of their first segment (as every graph edge list is built in segment
  // order: deterministic and independent of where the walks began).
  std::sort(spans.begin(), spans.end(),
            [](const PlaneGraph::Chain& x, const PlaneGraph::Chain& y) { return x.first < y.first; });

  // Vertices. A piece (fragment of a touched segment) ends where the next one along its ring
  // starts: the next fragment of its segment, or the first piece or chain of the next segment
  // (snap rounding never moves an input vertex, so a segment's fragments run from its start to
  // its end). So the starts of pieces and chains are all the vertex occurrences, and sorting
  // them once by key both numbers the vertices and gives every piece and chain its end ids,
  // with half the keys of sorting both ends and no search.
  struct Start {
    std::uint64_t key;
    std::uint32_t occurrence;  // index into occurrence_vertex
  };
  constexpr std::uint32_t kNone = 0xffffffffu;
  RecycledVector<struct FirstOccurrenceBuffer, std::uint32_t> first_occurrence;
  first_occurrence.assign(n, kNone);  // of segment s's start
  // Of segment s, when its ring successor starts elsewhere.
  RecycledVector<struct OwnEndBuffer, std::uint32_t> own_end;
  RecycledVector<struct PiecesBuffer, Piece> pieces;
  RecycledVector<struct StartsBuffer, Start> starts;
  std::size_t piece_count = 0;
  for (const std::uint32_t s : touched_ids)
    piece_count += listed(s) ? first_fragment[s + 1] - first_fragment[s] : 1;
  pieces.reserve(piece_count);
  starts.reserve(piece_count + spans.size());
  for (const PlaneGraph::Chain& c : spans) {
    first_occurrence[c.first] = static_cast<std::uint32_t>(starts.size());
    starts.push_back({key_of(segments[c.first].a), static_cast<std::uint32_t>(starts.size())});
  }
  // Piece i starts at occurrence piece_base + i.
  const auto piece_base = static_cast<std::uint32_t>(starts.size());
  // Written by index (sized once): this loop runs once per fragment.
  starts.resize(piece_base + piece_count);
  pieces.resize(piece_count);
  std::uint32_t occurrence = piece_base;
  auto add_piece = [&](Point64 start, std::int32_t polygon, std::uint8_t channel) {
    starts[occurrence] = {key_of(start), occurrence};
    // The direction (sign) is set once the end ids are known.
    pieces[occurrence - piece_base] = {0, 0, polygon, channel, 0};
    ++occurrence;
  };
  for (const std::uint32_t s : touched_ids) {
    first_occurrence[s] = occurrence;
    const std::int32_t polygon = polygon_of[s];
    const std::uint8_t channel = channel_of[s];
    if (!listed(s)) {  // its own single piece
      add_piece(segments[s].a, polygon, channel);
      continue;
    }
    Point64 expected = segments[s].a;
    for (std::uint32_t k = first_fragment[s]; k < first_fragment[s + 1]; ++k) {
      const Segment& f = fragments[k].seg;
      if (f.a != expected)  // Not reached by tests: snap rounding's fragments run end to end.
        throw std::logic_error("plane graph: the fragments of a segment do not run end to end");
      expected = f.b;
      add_piece(f.a, polygon, channel);
    }
    if (expected != segments[s].b)  // Not reached by tests (as above).
      throw std::logic_error("plane graph: the fragments of a segment do not run end to end");
  }
  // Segments that are not in rings (hole splitting's pieces) end where nothing starts.
  for (const std::uint32_t s : touched_ids)
    if (segments[next[s]].a != segments[s].b) {
      if (own_end.empty()) own_end.assign(n, kNone);
      own_end[s] = static_cast<std::uint32_t>(starts.size());
      starts.push_back({key_of(segments[s].b), static_cast<std::uint32_t>(starts.size())});
    }
  radix_sort(starts, [](const Start& x) { return x.key; });
  RecycledVector<struct KeysBuffer, std::uint64_t> keys;
  keys.reserve(starts.size());
  RecycledVector<struct OccurrenceVertexBuffer, std::uint32_t> occurrence_vertex;
  occurrence_vertex.resize(starts.size());
  for (const Start& st : starts) {
    if (keys.empty() || keys.back() != st.key) keys.push_back(st.key);
    occurrence_vertex[st.occurrence] = static_cast<std::uint32_t>(keys.size() - 1);
  }
  // The vertex where segment s ends: where the segment after it along its ring starts.
  auto end_vertex = [&](std::uint32_t s) {
    const std::uint32_t o =
        own_end.empty() || own_end[s] == kNone ? first_occurrence[next[s]] : own_end[s];
    if (o == kNone) throw std::logic_error("plane graph: a segment ends inside a chain");
    return occurrence_vertex[o];
  };
  {
    std::uint32_t i = 0;
    for (const std::uint32_t s : touched_ids) {
      const std::uint32_t count = listed(s) ? first_fragment[s + 1] - first_fragment[s] : 1;
      const std::int32_t weight = input.weight_of(s);
      for (std::uint32_t k = 0; k < count; ++k, ++i) {
        const std::uint32_t a = occurrence_vertex[piece_base + i];
        const std::uint32_t b = k + 1 == count ? end_vertex(s) : occurrence_vertex[piece_base + i + 1];
        Piece& piece = pieces[i];
        piece.net = a < b ? weight : -weight;
        piece.lo = std::min(a, b);
        piece.hi = std::max(a, b);
      }
    }
  }
  // g's arrays are reused (their capacity kept): every one is sized or cleared below.
  g.chain.clear();
  g.around.clear();
  g.turn_at.clear();
  g.cancelled_edges = 0;
  const std::size_t edge_bound = pieces.size() + spans.size();
  g.chain.reserve(edge_bound);
  g.vertices.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) g.vertices[i] = point_of(keys[i]);
  // Sorted by (lo, hi), stably: two counting sorts (vertex ids are small), by hi and then by
  // lo. (Sorting each lo's short run by hi instead branched unpredictably on every piece.)
  counting_sort(pieces, keys.size(), [](const Piece& p) { return p.hi; });
  counting_sort(pieces, keys.size(), [](const Piece& p) { return p.lo; });
  // Merge pieces with equal endpoints, summing multiplicities per (channel, polygon). Most
  // edges have one piece: written straight out. In a larger group the pieces come in segment
  // order, which is already (channel, polygon) order for clip's operands (the sorts are
  // stable); one that is not (hole splitting's bridges) is put in order first.
  auto tag_less = [](const Piece& x, const Piece& y) {
    return std::tie(x.channel, x.polygon) < std::tie(y.channel, y.polygon);
  };
  // Written by index into arrays sized for the most edges there can be, then trimmed: one
  // store per field instead of a capacity check per push.
  g.segments = &segments;
  g.origin_of.resize(2 * edge_bound);
  g.mult_begin.resize(edge_bound + 1);
  g.mults.resize(edge_bound);
  g.mult_begin[0] = 0;
  std::uint32_t edges = 0, mult_count = 0;
  auto close_edge = [&](std::uint32_t lo, std::uint32_t hi, std::uint32_t first_mult) {
    if (mult_count == first_mult) {
      ++g.cancelled_edges;
      return;
    }
    g.origin_of[2 * edges] = lo;
    g.origin_of[2 * edges + 1] = hi;
    g.mult_begin[++edges] = mult_count;
  };
  for (std::size_t i = 0; i < pieces.size();) {
    const std::uint32_t lo = pieces[i].lo, hi = pieces[i].hi;
    std::size_t j = i + 1;
    while (j < pieces.size() && pieces[j].lo == lo && pieces[j].hi == hi) ++j;
    const std::uint32_t first_mult = mult_count;
    if (j == i + 1) {  // (a merged stretch of weight 0 cancels alone)
      if (pieces[i].net != 0)
        g.mults[mult_count++] = {pieces[i].channel, pieces[i].polygon, pieces[i].net};
    } else {
      if (!std::is_sorted(pieces.begin() + i, pieces.begin() + j, tag_less))
        std::stable_sort(pieces.begin() + i, pieces.begin() + j, tag_less);
      for (std::size_t k = i; k < j;) {
        std::size_t m = k;
        std::int32_t net = 0;
        for (; m < j && pieces[m].channel == pieces[k].channel && pieces[m].polygon == pieces[k].polygon; ++m)
          net += pieces[m].net;
        if (net != 0) g.mults[mult_count++] = {pieces[k].channel, pieces[k].polygon, net};
        k = m;
      }
    }
    close_edge(lo, hi, first_mult);
    i = j;
  }
  g.chain.resize(edges);  // fragment edges: count 0

  // Chains: nothing else meets an untouched segment, so no other edge can coincide with one.
  for (PlaneGraph::Chain c : spans) {
    const std::uint32_t last = c.ring_begin + (c.first - c.ring_begin + c.count) % c.ring_len;
    std::uint32_t a = occurrence_vertex[first_occurrence[c.first]], b = end_vertex(last);
    if (a == b) throw std::logic_error("plane graph: a chain is a loop");
    std::int32_t net = input.weight_of(c.first);
    if (b < a) {
      std::swap(a, b);
      c.reversed = true;
      net = -net;
    }
    if (net == 0) throw std::logic_error("plane graph: a chain of weight 0");  // (only merged
    // stretches weigh 0, and they are never chained)
    g.mults[mult_count++] = {channel_of[c.first], polygon_of[c.first], net};
    close_edge(a, b, mult_count - 1);
    g.chain.push_back(c);
  }
  g.origin_of.resize(2 * std::size_t{edges});
  g.mult_begin.resize(edges + 1);
  g.mults.resize(mult_count);

  // Half-edges around each vertex, sorted by the angle of their first step. Each half-edge's
  // direction is read once (first_step walks chain indirections); most vertices have two to
  // four half-edges.
  const std::size_t nv = g.vertices.size(), nh = 2 * g.edge_count();
  g.around_begin.assign(nv + 1, 0);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    ++g.around_begin[g.from(e) + 1];
    ++g.around_begin[g.to(e) + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) g.around_begin[v + 1] += g.around_begin[v];
  RecycledVector<struct OutBuffer, Out> out;
  out.resize(nh);
  {
    RecycledVector<struct FillBuffer, std::uint32_t> fill;
    fill.assign(g.around_begin.begin(), g.around_begin.end() - 1);
    for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
      const std::uint32_t a = g.from(e), b = g.to(e);
      const Point64 pa = g.vertices[a], pb = g.vertices[b];
      const std::uint32_t m = g.chain[e].count;
      const Point64 step_a = m == 0 ? pb : g.interior_point(e, 0);
      const Point64 step_b = m == 0 ? pa : g.interior_point(e, m - 1);
      out[fill[a]++] = {{step_a.x - pa.x, step_a.y - pa.y}, 2 * e};
      out[fill[b]++] = {{step_b.x - pb.x, step_b.y - pb.y}, 2 * e + 1};
    }
  }
  auto before = [](const Out& x, const Out& y) { return angle_less(x.d, y.d); };
  g.around.resize(nh);
  g.turn_at.resize(nh);
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
    if (e - b <= kRankedDegree) {
      place_by_rank(out.data() + b, e - b, b, g);
      continue;
    }
    sort_short_run(out.begin() + b, out.begin() + e, before);
    for (std::uint32_t k = b; k < e; ++k) {
      g.around[k] = out[k].h;
      g.turn_at[out[k].h ^ 1] = k == b ? e - 1 : k - 1;
    }
  }
}

}  // namespace edgeland::detail
