// Edge collection (clip/src/input_edges.hpp): append_ring_edges against the definition. For each
// ring chosen (all, or the `which` list in its order) the edges are its consecutive point pairs
// with repeated points skipped, consecutive in the list, tagged (channel, polygon index or 0),
// linked by next[] round the ring, with no weights; edges already in the list stay as they were.
#include "input_edges.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

using detail::EdgeList;

// The expected segments of one ring: each point to the next, cyclically, except where the two
// are equal.
std::vector<Segment> nonzero_edges(const Ring& ring) {
  std::vector<Segment> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a != b) out.push_back({a, b});
  }
  return out;
}

// Checks out[first ..] against the rings chosen by `which` (all when null).
void expect_appended(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                     const std::vector<std::uint32_t>* which, const EdgeList& out,
                     std::uint32_t first) {
  std::vector<std::uint32_t> chosen;
  if (which) {
    chosen = *which;
  } else {
    for (std::uint32_t k = 0; k < rings.size(); ++k) chosen.push_back(k);
  }
  std::uint32_t at = first;
  for (std::uint32_t k : chosen) {
    const std::vector<Segment> want = nonzero_edges(rings[k]);
    const std::uint32_t begin = at;
    for (std::size_t i = 0; i < want.size(); ++i, ++at) {
      RC_ASSERT(at < out.size());
      RC_ASSERT(out.segments[at] == want[i]);
      RC_ASSERT(out.channel[at] == channel);
      RC_ASSERT(out.polygon[at] == (tag_polygons ? static_cast<std::int32_t>(k) : 0));
      // next[] runs round the ring: to the following edge, the last one back to the first.
      RC_ASSERT(out.next[at] == (i + 1 == want.size() ? begin : at + 1));
    }
  }
  RC_ASSERT(out.size() == at);
  RC_ASSERT(out.channel.size() == at);
  RC_ASSERT(out.polygon.size() == at);
  RC_ASSERT(out.next.size() == at);
  RC_ASSERT(out.weight.empty());
}

RC_GTEST_PROP(InputEdges, EdgesOfEachRingAreConsecutiveTaggedAndLinked, ()) {
  const std::vector<Ring> rings = *stages::crowded_rings(6, 12);
  const auto channel = static_cast<std::uint8_t>(stages::uniform(0, 1));
  const bool tag_polygons = (stages::uniform(0, 1) == 1);
  // A subset of the rings in any order, or all of them.
  std::optional<std::vector<std::uint32_t>> which;
  if ((stages::uniform(0, 1) == 1)) {
    which.emplace();
    for (std::uint32_t k = 0; k < rings.size(); ++k)
      if ((stages::uniform(0, 1) == 1)) which->push_back(k);
    for (std::size_t i = which->size(); i > 1; --i)  // Fisher-Yates, drawn by RapidCheck
      std::swap(
          (*which)[i - 1],
          (*which)[static_cast<std::size_t>(stages::uniform(0, static_cast<std::int64_t>(i) - 1))]);
  }
  // Edges already in the list (another operand) must stay as they are.
  EdgeList out;
  const std::vector<Ring> before = *stages::crowded_rings(2, 5);
  detail::append_ring_edges(before, detail::kSubjectChannel, true, out);
  const EdgeList copy = out;
  const auto first = static_cast<std::uint32_t>(out.size());
  detail::append_ring_edges(rings, channel, tag_polygons, out, which ? &*which : nullptr);
  for (std::uint32_t i = 0; i < first; ++i) {
    RC_ASSERT(out.segments[i] == copy.segments[i]);
    RC_ASSERT(out.channel[i] == copy.channel[i]);
    RC_ASSERT(out.polygon[i] == copy.polygon[i]);
    RC_ASSERT(out.next[i] == copy.next[i]);
  }
  expect_appended(rings, channel, tag_polygons, which ? &*which : nullptr, out, first);
}

TEST(InputEdges, RepeatedPointsAreSkippedAndDegenerateRingsVanish) {
  // A square with repeated points (also first == last), a ring of one repeated point, an empty
  // ring, and a two-point ring that runs there and back.
  const std::vector<Ring> rings{{{0, 0}, {0, 0}, {4, 0}, {4, 4}, {4, 4}, {0, 4}, {0, 0}},
                                {{7, 7}, {7, 7}, {7, 7}},
                                {},
                                {{1, 1}, {3, 2}}};
  EdgeList out;
  detail::append_ring_edges(rings, detail::kClipChannel, true, out);
  const std::vector<Segment> want{{{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}},
                                  {{0, 4}, {0, 0}}, {{1, 1}, {3, 2}}, {{3, 2}, {1, 1}}};
  EXPECT_EQ(out.segments, want);
  EXPECT_EQ(out.next, (std::vector<std::uint32_t>{1, 2, 3, 0, 5, 4}));
  EXPECT_EQ(out.polygon, (std::vector<std::int32_t>{0, 0, 0, 0, 3, 3}));
  EXPECT_EQ(out.channel, std::vector<std::uint8_t>(6, detail::kClipChannel));
  EXPECT_TRUE(out.weight.empty());
  for (std::uint32_t i = 0; i < out.size(); ++i) EXPECT_EQ(out.weight_of(i), 1);
}

TEST(InputEdges, WhichPicksRingsInItsOrderAndTagsThemByIndex) {
  const std::vector<Ring> rings{
      {{0, 0}, {1, 0}, {0, 1}}, {{5, 5}, {6, 5}, {5, 6}}, {{9, 9}, {10, 9}, {9, 10}}};
  const std::vector<std::uint32_t> which{2, 0};
  EdgeList out;
  detail::append_ring_edges(rings, detail::kSubjectChannel, true, out, &which);
  ASSERT_EQ(out.size(), 6u);
  EXPECT_EQ(out.segments[0], (Segment{{9, 9}, {10, 9}}));
  EXPECT_EQ(out.segments[3], (Segment{{0, 0}, {1, 0}}));
  EXPECT_EQ(out.polygon, (std::vector<std::int32_t>{2, 2, 2, 0, 0, 0}));
  EXPECT_EQ(out.next, (std::vector<std::uint32_t>{1, 2, 0, 4, 5, 3}));
  // Untagged: every edge polygon 0.
  EdgeList untagged;
  detail::append_ring_edges(rings, detail::kSubjectChannel, false, untagged, &which);
  EXPECT_EQ(untagged.polygon, std::vector<std::int32_t>(6, 0));
}

}  // namespace
}  // namespace edgeland::test
