#include "segment_index.hpp"

namespace edgeland::detail {
namespace {

int sign(std::int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

SegmentIndex::SegmentIndex(const std::vector<Segment>& segments,
                           const std::vector<std::uint32_t>& next) {
  const std::uint32_t n = static_cast<std::uint32_t>(segments.size());
  segments_ = &segments;
  // Greedy runs: extend while the next segment follows along the ring and keeps the run's
  // x and y directions (a zero component agrees with either).
  std::uint32_t ring = 0;
  for (std::uint32_t s = 0; s < n;) {
    if (s > 0 && next[s - 1] != s) ring = s;  // rings occupy consecutive ids
    int dx = sign(segments[s].b.x - segments[s].a.x), dy = sign(segments[s].b.y - segments[s].a.y);
    std::uint32_t last = s;
    while (last + 1 < n && next[last] == last + 1 && last + 1 - s < kRunLength) {
      const Segment& t = segments[last + 1];
      const int tx = sign(t.b.x - t.a.x), ty = sign(t.b.y - t.a.y);
      if ((tx != 0 && dx != 0 && tx != dx) || (ty != 0 && dy != 0 && ty != dy)) break;
      if (dx == 0) dx = tx;
      if (dy == 0) dy = ty;
      ++last;
    }
    runs_.push_back({s, last, ring, dx < 0});
    s = last + 1;
  }
  run_boxes_.resize(runs_.size());
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    run_boxes_[r] = {segments[runs_[r].first].a, segments[runs_[r].first].a};
    run_boxes_[r].expand(segments[runs_[r].last].b);
  }
}

}  // namespace edgeland::detail
