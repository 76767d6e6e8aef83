// check_plane_graph (stage_checks.hpp): the plane graph's promises to labeling and assembly.
#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/assert.hpp"
#include "stage_check_text.hpp"
#include "stage_checks.hpp"

namespace edgeland::detail {
namespace {

constexpr const char* kStage = "plane graph";

std::string num(std::size_t i) { return std::to_string(i); }

void expect_size(const char* what, std::size_t size, std::size_t expected) {
  if (size != expected)
    fail_stage(kStage, std::string("sizes: ") + what + " has " + num(size) + " entries, not " +
                           num(expected));
}

void check_sizes(const PlaneGraph& g) {
  if (g.origin_of.size() % 2 != 0)
    fail_stage(kStage, "sizes: origin_of has an odd size " + num(g.origin_of.size()));
  const std::size_t edges = g.edge_count();
  expect_size("chain", g.chain.size(), edges);
  expect_size("mult_begin", g.mult_begin.size(), edges + 1);
  expect_size("around", g.around.size(), 2 * edges);
  expect_size("turn_at", g.turn_at.size(), 2 * edges);
  expect_size("around_begin", g.around_begin.size(), g.vertices.size() + 1);
}

void check_vertices_and_ends(const PlaneGraph& g) {
  for (std::size_t v = 1; v < g.vertices.size(); ++v)
    if (!(g.vertices[v - 1] < g.vertices[v]))
      fail_stage(kStage, "vertex order: vertex " + num(v - 1) + " " + text(g.vertices[v - 1]) +
                             " is not below vertex " + num(v) + " " + text(g.vertices[v]));
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (g.to(e) >= g.vertices.size())
      fail_stage(kStage, "edge ends: edge " + num(e) + " ends at vertex " + num(g.to(e)) + " of " +
                             num(g.vertices.size()));
    if (g.from(e) >= g.to(e))
      fail_stage(kStage, "edge ends: edge " + num(e) + " runs from vertex " + num(g.from(e)) +
                             " to vertex " + num(g.to(e)) + " (from must be below to)");
  }
}

// A compressed row index: begin[0] == 0, nondecreasing, ending at `total`.
void check_csr(const char* rule, const std::vector<std::uint32_t>& begin, std::size_t total) {
  if (begin.front() != 0)
    fail_stage(kStage, std::string(rule) + ": starts at " + num(begin.front()) + ", not 0");
  for (std::size_t i = 1; i < begin.size(); ++i)
    if (begin[i] < begin[i - 1])
      fail_stage(kStage, std::string(rule) + ": entry " + num(i) + " (" + num(begin[i]) +
                             ") is below entry " + num(i - 1) + " (" + num(begin[i - 1]) + ")");
  if (begin.back() != total)
    fail_stage(kStage,
               std::string(rule) + ": ends at " + num(begin.back()) + ", not at " + num(total));
}

void check_multiplicities(const PlaneGraph& g) {
  check_csr("multiplicity CSR", g.mult_begin, g.mults.size());
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k) {
      const Multiplicity& m = g.mults[k];
      auto which = [&] { return "multiplicity: entry " + num(k) + " (of edge " + num(e) + ")"; };
      if (m.net == 0) fail_stage(kStage, which() + " has net 0");
      if (m.channel > 1) fail_stage(kStage, which() + " has channel " + num(m.channel));
      if (m.polygon < 0) fail_stage(kStage, which() + " has polygon " + std::to_string(m.polygon));
      if (k == g.mult_begin[e]) continue;
      const Multiplicity& p = g.mults[k - 1];
      if (std::tie(p.channel, p.polygon) >= std::tie(m.channel, m.polygon))
        fail_stage(kStage, which() + " (channel " + num(m.channel) + ", polygon " +
                               std::to_string(m.polygon) +
                               ") does not follow the one before it in (channel, polygon) order");
    }
}

// A chain edge's record: within its ring and the segment list, and its ends are the edge's.
void check_chain(const PlaneGraph& g, std::uint32_t e) {
  const PlaneGraph::Chain& c = g.chain[e];
  auto which = [&] {
    return "chain record: edge " + num(e) + " (" + num(c.count) + " interior points)";
  };
  if (!g.segments) fail_stage(kStage, which() + " has no segment list");
  const std::size_t ring_end = std::size_t{c.ring_begin} + c.ring_len;
  if (ring_end > g.segments->size() || c.first < c.ring_begin || c.first >= ring_end ||
      c.count >= c.ring_len)
    fail_stage(kStage, which() + " starts at segment " + num(c.first) + " of ring [" +
                           num(c.ring_begin) + ", " + num(ring_end) + ") in " +
                           num(g.segments->size()) + " segments");
  const std::size_t last = c.ring_begin + (c.first - c.ring_begin + c.count) % c.ring_len;
  const Point64 start = (*g.segments)[c.first].a, end = (*g.segments)[last].b;
  const Point64 from = g.vertices[g.from(e)], to = g.vertices[g.to(e)];
  if ((c.reversed ? to : from) != start || (c.reversed ? from : to) != end)
    fail_stage(kStage, which() + " runs " + text(start) + " to " + text(end) +
                           (c.reversed ? " reversed" : "") + " between vertices " + text(from) +
                           " and " + text(to));
}

void check_chains(const PlaneGraph& g) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (g.chain[e].count > 0) check_chain(g, e);
}

// Where each half-edge sits in `around`, checking that each appears once, in its origin's range.
std::vector<std::uint32_t> around_positions(const PlaneGraph& g) {
  check_csr("around CSR", g.around_begin, g.around.size());
  constexpr std::uint32_t kAbsent = 0xffffffffu;
  std::vector<std::uint32_t> position(g.around.size(), kAbsent);
  for (std::uint32_t v = 0; v + 1 < g.around_begin.size(); ++v)
    for (std::uint32_t k = g.around_begin[v]; k < g.around_begin[v + 1]; ++k) {
      const std::uint32_t h = g.around[k];
      if (h >= position.size())
        fail_stage(kStage, "around: position " + num(k) + " holds half-edge " + num(h) + " of " +
                               num(position.size()));
      if (position[h] != kAbsent)
        fail_stage(kStage, "around: half-edge " + num(h) + " at positions " + num(position[h]) +
                               " and " + num(k));
      if (g.origin(h) != v)
        fail_stage(kStage, "around: half-edge " + num(h) + " from vertex " + num(g.origin(h)) +
                               " is listed around vertex " + num(v));
      position[h] = k;
    }
  return position;  // complete: as many positions as half-edges, none twice
}

Point64 first_direction(const PlaneGraph& g, std::uint32_t h) {
  const Point64 o = g.vertices[g.origin(h)], t = g.first_step(h);
  return {t.x - o.x, t.y - o.y};
}

void check_angle_order(const PlaneGraph& g) {
  for (std::uint32_t v = 0; v < g.vertices.size(); ++v) {
    const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
    for (std::uint32_t k = b; k < e; ++k) {
      const Point64 d = first_direction(g, g.around[k]);
      if (d == Point64{0, 0})
        fail_stage(kStage,
                   "zero first step: half-edge " + num(g.around[k]) + " at vertex " + num(v));
      if (k == b) continue;
      const Point64 before = first_direction(g, g.around[k - 1]);
      if (angle_less(before, d)) continue;
      const std::string where = "half-edges " + num(g.around[k - 1]) + " and " + num(g.around[k]) +
                                " at vertex " + num(v) + " " + text(g.vertices[v]);
      if (!angle_less(d, before))
        fail_stage(kStage, "same direction: " + where + " both leave towards " + text(d));
      fail_stage(kStage, "angle order: " + where + " (positions " + num(k - 1) + ", " + num(k) +
                             ") are not in counter-clockwise order");
    }
  }
}

// turn_at[h]: at target(h), the position just clockwise of twin(h) (wrapping round).
void check_turns(const PlaneGraph& g, const std::vector<std::uint32_t>& position) {
  for (std::uint32_t h = 0; h < g.turn_at.size(); ++h) {
    const std::uint32_t v = g.target(h), p = position[h ^ 1];
    const std::uint32_t expected = (p == g.around_begin[v] ? g.around_begin[v + 1] : p) - 1;
    if (g.turn_at[h] != expected)
      fail_stage(kStage, "turn_at: half-edge " + num(h) + " turns to position " +
                             num(g.turn_at[h]) + ", not " + num(expected) +
                             " (clockwise of its twin at vertex " + num(v) + ")");
  }
}

}  // namespace

void check_plane_graph(const PlaneGraph& g) {
  check_sizes(g);
  check_vertices_and_ends(g);
  check_multiplicities(g);
  check_chains(g);
  const std::vector<std::uint32_t> position = around_positions(g);
  check_angle_order(g);
  check_turns(g, position);
}

}  // namespace edgeland::detail
