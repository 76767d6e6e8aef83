#include "face_tracing.hpp"

#include <algorithm>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/assert.hpp"
#include "point_key.hpp"

namespace edgeland::detail {
namespace {

// The loops of a closed walk of points split where it revisits a point, each visiting every
// point once.
void split_at_repeats(const std::vector<Point64>& walk, std::vector<ScratchRing>& out) {
  // Most walks visit every point once: one sorted copy tells, and then the walk is the loop.
  ScratchVector<std::uint64_t> keys;
  keys.resize(walk.size());
  for (std::size_t i = 0; i < walk.size(); ++i) keys[i] = point_key(walk[i]);
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) == keys.end()) {
    out.emplace_back().assign(walk.begin(), walk.end());
    return;
  }
  // (Not reached by the kernel, clip and spatial tests: no traced walk there revisits a point.)
  std::vector<Point64> stack;
  for (Point64 p : walk) {
    const auto it = std::find(stack.begin(), stack.end(), p);
    if (it != stack.end()) {
      out.emplace_back().assign(it, stack.end());
      stack.erase(it, stack.end());
    }
    stack.push_back(p);
  }
  if (!stack.empty()) out.emplace_back().assign(stack.begin(), stack.end());
}

// Where each point's group of leaving edges starts in the sorted `by_origin`: an open-addressing
// table keyed by point key, so the walk finds the edges leaving a point in one or two probes
// instead of a binary search over all edges (most of the tracing on a large region).
class OriginIndex {
 public:
  explicit OriginIndex(const ScratchVector<std::pair<std::uint64_t, std::uint32_t>>& by_origin) {
    std::size_t size = 16;
    while (size < 2 * by_origin.size()) size *= 2;
    mask_ = size - 1;
    keys_.assign(size, 0);
    first_.assign(size, kEmpty);
    for (std::size_t i = 0; i < by_origin.size(); ++i) {
      if (i > 0 && by_origin[i].first == by_origin[i - 1].first) continue;
      const std::size_t at = slot(by_origin[i].first);
      keys_[at] = by_origin[i].first;
      first_[at] = static_cast<std::uint32_t>(i);
    }
  }
  // The first index of the key's group in by_origin, or kEmpty when no edge leaves the point.
  std::uint32_t first(std::uint64_t key) const { return first_[slot(key)]; }
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

 private:
  // The key's slot, or the empty slot where it would go (at most half the slots are taken).
  std::size_t slot(std::uint64_t key) const {
    std::size_t at = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask_;
    while (first_[at] != kEmpty && keys_[at] != key) at = (at + 1) & mask_;
    return at;
  }

  std::size_t mask_ = 0;
  ScratchVector<std::uint64_t> keys_;
  ScratchVector<std::uint32_t> first_;
};

}  // namespace

void trace_faces(const std::vector<Segment>& edges, std::vector<ScratchRing>& out) {
  const std::size_t m = edges.size();
  auto direction = [&](std::uint32_t e) {
    return Point64{edges[e].b.x - edges[e].a.x, edges[e].b.y - edges[e].a.y};
  };
  // Edges grouped by origin (one packed key each), a group of several counter-clockwise by
  // angle: most points have one edge leaving them, and then there is nothing to choose.
  ScratchVector<std::pair<std::uint64_t, std::uint32_t>> by_origin;
  by_origin.resize(m);
  for (std::uint32_t i = 0; i < m; ++i) by_origin[i] = {point_key(edges[i].a), i};
  std::sort(by_origin.begin(), by_origin.end());
  for (std::size_t i = 0; i < m;) {
    std::size_t j = i + 1;
    while (j < m && by_origin[j].first == by_origin[i].first) ++j;
    if (j - i > 1)
      std::sort(by_origin.begin() + static_cast<std::ptrdiff_t>(i),
                by_origin.begin() + static_cast<std::ptrdiff_t>(j),
                [&](const auto& x, const auto& y) {
                  return angle_less(direction(x.second), direction(y.second));
                });
    i = j;
  }
  const OriginIndex origins(by_origin);
  // The edge after e: clockwise from e's reverse at its end, the first edge leaving there.
  auto next_of = [&](std::uint32_t e) {
    const std::uint64_t key = point_key(edges[e].b);
    const std::uint32_t at = origins.first(key);
    if (at == OriginIndex::kEmpty) fail_stage("hole splitting", "a face does not close");
    const auto lo = by_origin.begin() + at;
    auto hi = lo;
    while (hi != by_origin.end() && hi->first == key) ++hi;
    if (hi - lo == 1) return lo->second;
    const Point64 reverse{-direction(e).x, -direction(e).y};
    const auto it = std::lower_bound(lo, hi, reverse, [&](const auto& x, Point64 d) {
      return angle_less(direction(x.second), d);
    });
    return (it == lo ? hi - 1 : it - 1)->second;
  };
  ScratchVector<std::uint8_t> used;
  used.assign(m, 0);
  ScratchVector<Point64> walk;
  for (std::uint32_t start = 0; start < m; ++start) {
    if (used[start]) continue;
    walk.clear();
    std::uint32_t e = start;
    do {
      used[e] = 1;
      walk.push_back(edges[e].a);
      e = next_of(e);
    } while (e != start && !used[e]);
    if (e != start) fail_stage("hole splitting", "a face does not close");
    split_at_repeats(walk, out);
  }
}

}  // namespace edgeland::detail
