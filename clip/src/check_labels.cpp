// check_labels (stage_checks.hpp): labeling's promises to assembly. The crossing rule is
// written here from labeling.hpp's definition of the states, not taken from labeling.cpp, so
// the two are independent statements of one rule.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/assert.hpp"
#include "stage_checks.hpp"

namespace edgeland::detail {
namespace {

constexpr const char* kStage = "labeling";

std::string num(std::size_t i) { return std::to_string(i); }

std::string text(const SideState& s) {
  std::string out = "{";  // appended: see point_text.hpp
  out += std::to_string(s.by_channel[0]);
  out += ' ';
  out += std::to_string(s.by_channel[1]);
  out += '}';
  return out;
}

// +1 for half-edge 2e (nets are counted along it), -1 for its twin.
std::int32_t direction_sign(std::uint32_t h) { return (h & 1) ? -1 : 1; }

// A count channel after crossing h from its right: every net of that channel (of all channels
// when `channel` is negative) counted along h.
std::int32_t count_after(const PlaneGraph& g, std::uint32_t h, int channel, std::int32_t count) {
  const std::uint32_t e = h >> 1;
  for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k)
    if (channel < 0 || g.mults[k].channel == channel) count += direction_sign(h) * g.mults[k].net;
  return count;
}

// An owner channel after crossing h from its right: the smallest polygon of the channel
// entered (positive net along h), else none if the owner is left (negative net), else the same.
std::int32_t owner_after(const PlaneGraph& g, std::uint32_t h, int channel, std::int32_t owner) {
  const std::uint32_t e = h >> 1;
  std::int32_t entered = -1;
  bool owner_left = false;
  for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k) {
    const Multiplicity& m = g.mults[k];
    if (m.channel != channel) continue;
    const std::int32_t net = direction_sign(h) * m.net;
    if (net > 0 && (entered < 0 || m.polygon < entered)) entered = m.polygon;
    if (net < 0 && m.polygon == owner) owner_left = true;
  }
  return entered >= 0 ? entered : owner_left ? -1 : owner;
}

// The state on h's left, from the state on its right (labeling.hpp, LabelMode).
SideState crossed(const PlaneGraph& g, LabelMode mode, SideState right, std::uint32_t h) {
  SideState out = right;
  switch (mode) {
    case LabelMode::kWinding:
      out.by_channel[0] = count_after(g, h, -1, right.by_channel[0]);
      break;
    case LabelMode::kOwnerAndCount:
      out.by_channel[0] = owner_after(g, h, 0, right.by_channel[0]);
      out.by_channel[1] = count_after(g, h, 1, right.by_channel[1]);
      break;
    case LabelMode::kOwner:
      out.by_channel[0] = owner_after(g, h, 0, right.by_channel[0]);
      out.by_channel[1] = owner_after(g, h, 1, right.by_channel[1]);
      break;
  }
  return out;
}

// Whether s holds values its mode allows (labeling.hpp, LabelMode).
bool state_allowed(const SideState& s, LabelMode mode) {
  switch (mode) {
    case LabelMode::kWinding:
      return s.by_channel[1] == 0;
    case LabelMode::kOwnerAndCount:
      return s.by_channel[0] >= -1 && s.by_channel[1] >= 0;
    case LabelMode::kOwner:
      return s.by_channel[0] >= -1 && s.by_channel[1] >= -1;
  }
  return false;  // Not reached: the switch covers every mode.
}

void check_state_ranges(LabelMode mode, const std::vector<SideState>& left) {
  for (std::size_t h = 0; h < left.size(); ++h)
    if (!state_allowed(left[h], mode))
      fail_stage(kStage, "state range: the left of half-edge " + num(h) + " has " + text(left[h]));
}

void check_faces(const PlaneGraph& g, const std::vector<SideState>& left) {
  for (std::uint32_t h = 0; h < left.size(); ++h) {
    const std::uint32_t next = g.around[g.turn_at[h]];
    if (left[next] != left[h])
      fail_stage(kStage, "face: half-edge " + num(h) + " has " + text(left[h]) +
                             " on its left, the next half-edge " + num(next) +
                             " of that face has " + text(left[next]));
  }
}

void check_crossings(const PlaneGraph& g, LabelMode mode, const std::vector<SideState>& left) {
  for (std::uint32_t h = 0; h < left.size(); ++h) {
    const SideState expected = crossed(g, mode, left[h ^ 1], h);
    if (left[h] != expected)
      fail_stage(kStage, "crossing: edge " + num(h >> 1) + " from " + text(left[h ^ 1]) +
                             " across half-edge " + num(h) + " gives " + text(expected) +
                             ", but its left has " + text(left[h]));
  }
}

// The position at v of the half-edge whose counter-clockwise sector holds direction d.
std::uint32_t sector_of(const PlaneGraph& g, std::uint32_t v, Point64 d) {
  const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
  std::uint32_t k = e - 1;  // no half-edge before d: the sector wrapping round angle 0
  for (std::uint32_t i = b; i < e; ++i) {
    const Point64 o = g.vertices[v], t = g.first_step(g.around[i]);
    if (angle_less({t.x - o.x, t.y - o.y}, d)) k = i;
  }
  return k;
}

void check_outer_face(const PlaneGraph& g, LabelMode mode, const std::vector<SideState>& left) {
  std::uint32_t v = 0;
  while (v < g.vertices.size() && g.around_begin[v] == g.around_begin[v + 1]) ++v;
  if (v == g.vertices.size()) return;  // no edges
  const std::uint32_t h = g.around[sector_of(g, v, {-1, 0})];
  if (left[h] != empty_state(mode))
    fail_stage(kStage, "outer face: west of the smallest vertex " + num(v) +
                           ", the left of half-edge " + num(h) + " has " + text(left[h]) +
                           ", not the empty state " + text(empty_state(mode)));
}

}  // namespace

void check_labels(const PlaneGraph& g, LabelMode mode, const std::vector<SideState>& left) {
  if (left.size() != 2 * g.edge_count())
    fail_stage(kStage, "size: " + num(left.size()) + " states for " + num(2 * g.edge_count()) +
                           " half-edges");
  check_state_ranges(mode, left);
  check_faces(g, left);
  check_crossings(g, mode, left);
  check_outer_face(g, mode, left);
}

}  // namespace edgeland::detail
