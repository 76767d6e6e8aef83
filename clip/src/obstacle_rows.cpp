#include "obstacle_rows.hpp"

#include <algorithm>

namespace edgeland::detail {
namespace {

constexpr std::size_t kPerRow = 8;  // ring edges a row holds on average
constexpr std::size_t kMaxRows = 1 << 16;

// y - y_min as an unsigned count (exact for any two coordinates with y >= y_min).
std::uint64_t offset(std::int64_t y, std::int64_t y_min) {
  return static_cast<std::uint64_t>(y) - static_cast<std::uint64_t>(y_min);
}

bool meets(const Segment& s, std::int64_t lo, std::int64_t hi) {
  return std::max(s.a.y, s.b.y) >= lo && std::min(s.a.y, s.b.y) <= hi;
}

}  // namespace

ObstacleRows::ObstacleRows(const std::vector<Segment>& edges,
                           const std::vector<Point64>& vertices) {
  by_y_.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    by_y_[i] = {vertices[i].y, static_cast<std::uint32_t>(i)};
  std::sort(by_y_.begin(), by_y_.end());
  const std::size_t n = std::clamp<std::size_t>(edges.size() / kPerRow, 1, kMaxRows);
  if (!by_y_.empty()) {
    y_min_ = by_y_.front().first;
    row_height_ = offset(by_y_.back().first, y_min_) / n + 1;  // n rows cover every vertex
  }
  first_.assign(n + 1, 0);
  const auto each_row = [&](const Segment& s, auto&& f) {
    const std::size_t last = row(std::max(s.a.y, s.b.y));
    for (std::size_t r = row(std::min(s.a.y, s.b.y)); r <= last; ++r) f(r);
  };
  for (const Segment& s : edges) each_row(s, [&](std::size_t r) { ++first_[r + 1]; });
  for (std::size_t r = 0; r < n; ++r) first_[r + 1] += first_[r];
  filed_.resize(first_[n]);
  ScratchVector<std::uint32_t> at;
  at.assign(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i)
    each_row(edges[i], [&](std::size_t r) { filed_[at[r]++] = static_cast<std::uint32_t>(i); });
  bridge_head_.assign(n, kNone);
  bridge_tail_.assign(n, kNone);
}

std::size_t ObstacleRows::row(std::int64_t y) const {
  if (y <= y_min_) return 0;
  return std::min<std::size_t>(rows() - 1, offset(y, y_min_) / row_height_);
}

// Appended to the tail of each row it crosses, so every row's list stays ascending.
void ObstacleRows::add_bridge(std::uint32_t index, const Segment& s) {
  const std::size_t last = row(std::max(s.a.y, s.b.y));
  for (std::size_t r = row(std::min(s.a.y, s.b.y)); r <= last; ++r) {
    const auto at = static_cast<std::uint32_t>(bridges_.size());
    bridges_.push_back({index, kNone, s});
    if (bridge_tail_[r] == kNone)
      bridge_head_[r] = at;
    else
      bridges_[bridge_tail_[r]].next = at;
    bridge_tail_[r] = at;
  }
}

void ObstacleRows::obstacles_in(std::int64_t lo, std::int64_t hi, ScratchVector<std::uint32_t>& out,
                                bool ordered) const {
  out.clear();
  const std::size_t first = row(lo), last = row(hi);
  for (std::size_t r = first; r <= last; ++r) {
    out.insert(out.end(), filed_.begin() + first_[r], filed_.begin() + first_[r + 1]);
    for (std::uint32_t b = bridge_head_[r]; b != kNone; b = bridges_[b].next)
      if (meets(bridges_[b].s, lo, hi)) out.push_back(bridges_[b].index);
  }
  // One row: its ring edges, then its bridges, each ascending (bridges come after ring edges).
  if (ordered && first != last) {  // an obstacle of several rows is filed in each
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
}

void ObstacleRows::vertices_in(std::int64_t lo, std::int64_t hi,
                               ScratchVector<std::uint32_t>& out) const {
  out.clear();
  const auto first = std::lower_bound(by_y_.begin(), by_y_.end(), std::make_pair(lo, 0u));
  for (auto it = first; it != by_y_.end() && it->first <= hi; ++it) out.push_back(it->second);
}

}  // namespace edgeland::detail
