#include "segment_index.hpp"

#include <algorithm>

#include "edgeland/kernel/assert.hpp"

namespace edgeland::detail {
namespace {

int sign(std::int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

SegmentIndex::SegmentIndex(const std::vector<Segment>& segments,
                           const std::vector<std::uint32_t>& next, std::size_t flat_up_to)
    : segments_(&segments), next_(&next), flat_up_to_(flat_up_to) {}

SegmentIndex::RunEnd SegmentIndex::run_end(std::uint32_t s) const {
  // Greedy: extend while the next segment follows along the ring and keeps the run's x and y
  // directions (a zero component agrees with either).
  const std::vector<Segment>& segments = *segments_;
  const std::vector<std::uint32_t>& next = *next_;
  const auto n = static_cast<std::uint32_t>(segments.size());
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
  return {last, dx < 0};
}

void SegmentIndex::find_run_ends() const {
  const auto n = static_cast<std::uint32_t>(segments_->size());
  if (!run_ends_.empty() || n == 0) return;
  for (std::uint32_t s = 0; s < n; s = run_ends_.back().last + 1) run_ends_.push_back(run_end(s));
}

std::size_t SegmentIndex::run_length_x16() const {
  find_run_ends();
  return run_ends_.empty() ? 0 : 16 * segments_->size() / run_ends_.size();
}

void SegmentIndex::build_flat() const {
  const std::vector<Segment>& segments = *segments_;
  const std::vector<std::uint32_t>& next = *next_;
  if (!flat_.empty() || segments.empty()) return;
  const auto n = static_cast<std::uint32_t>(segments.size());
  ring_.resize(n);
  for (std::uint32_t s = 0, ring = 0; s < n; ++s) {
    if (s > 0 && next[s - 1] != s) ring = s;  // rings occupy consecutive ids
    ring_[s] = ring;
  }
  sort_flat();
}

void SegmentIndex::mark_runs() const {
  if (!continues_run_.empty()) return;
  find_run_ends();
  continues_run_.assign(segments_->size(), 1);
  std::uint32_t first = 0;
  for (const RunEnd& end : run_ends_) {
    continues_run_[first] = 0;
    first = end.last + 1;
  }
}

void SegmentIndex::sort_flat() const {
  const std::vector<Segment>& segments = *segments_;
  const auto n = static_cast<std::uint32_t>(segments.size());
  auto min_x = [&](std::uint32_t s) { return std::min(segments[s].a.x, segments[s].b.x); };
  std::int64_t lo = min_x(0), hi = lo;
  for (std::uint32_t s = 1; s < n; ++s) {
    lo = std::min(lo, min_x(s));
    hi = std::max(hi, min_x(s));
  }
  // Sorting one packed key (min x from the least, then id) per segment is a few times cheaper
  // than sorting the boxes by a two-field comparison.
  ScratchVector<std::uint64_t> keys;
  keys.resize(n);
  // Not reached by tests: coordinates within the bound span less than 2^32.
  if (static_cast<std::uint64_t>(hi - lo) >> 32 != 0) fail_stage("segment index", "span >= 2^32");
  for (std::uint32_t s = 0; s < n; ++s)
    keys[s] = static_cast<std::uint64_t>(min_x(s) - lo) << 32 | s;
  std::sort(keys.begin(), keys.end());
  flat_.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    const auto s = static_cast<std::uint32_t>(keys[k] & 0xffffffffu);
    const Box64 b = box(s);
    flat_[k] = {b.min.x, b.max.x, b.min.y, b.max.y, s};
  }
}

void SegmentIndex::build_runs() const {
  if (built_) return;
  built_ = true;
  const std::vector<Segment>& segments = *segments_;
  const std::vector<std::uint32_t>& next = *next_;
  find_run_ends();
  std::uint32_t ring = 0, s = 0;
  runs_.reserve(run_ends_.size());
  for (const RunEnd& end : run_ends_) {
    if (s > 0 && next[s - 1] != s) ring = s;  // rings occupy consecutive ids
    runs_.push_back({s, end.last, ring, end.x_decreasing});
    s = end.last + 1;
  }
  run_boxes_.resize(runs_.size());
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    run_boxes_[r] = {segments[runs_[r].first].a, segments[runs_[r].first].a};
    run_boxes_[r].expand(segments[runs_[r].last].b);
  }
}

}  // namespace edgeland::detail
