// relabel_near() (relabel.hpp): relabel() with the regions the shape cannot reach left out of
// the arrangement, the locality filter of clip() (clip_near.hpp) for labeled regions. Why the
// result is relabel()'s: clip/README.md, "Regions the shape cannot reach".
#include <algorithm>
#include <utility>

#include "box_sweep.hpp"
#include "canonical.hpp"
#include "edgeland/clip/relabel.hpp"
#include "grown_box.hpp"
#include "relabel_pipeline.hpp"
#include "valid_set_factory.hpp"

namespace edgeland {
namespace {

using detail::ScratchVector;

// Up to this many boxes a list is compared pairwise: sorting for a sweep costs more.
constexpr std::size_t kFewBoxes = 32;

std::uint32_t root_of(ScratchVector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The group of every piece (a representative piece): pieces of one label whose closed boxes
// meet are in one group. The pieces of a region share its bridges, and regions of one label
// that touch at a vertex share a point where two of their rings touch, which their bridges may
// end at: each such set is decomposed as a whole, so it goes in or stays out as a whole.
ScratchVector<std::uint32_t> groups_of(const std::vector<Box64>& boxes,
                                       std::span<const RegionLabel> labels) {
  ScratchVector<std::uint32_t> parent;
  parent.resize(boxes.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto join = [&](std::uint32_t i, std::uint32_t j) {
    if (labels[i] == labels[j]) parent[root_of(parent, i)] = root_of(parent, j);
  };
  if (boxes.size() <= kFewBoxes) {
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
      for (std::uint32_t j = 0; j < i; ++j)
        if (boxes[i].overlaps(boxes[j])) join(i, j);
  } else {
    detail::for_each_overlapping_pair(boxes, join);
  }
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = root_of(parent, i);
  return parent;
}

// Brings in every piece of a group that has a piece in play.
void whole_groups(const ScratchVector<std::uint32_t>& group, ScratchVector<std::uint8_t>& in) {
  ScratchVector<std::uint8_t> group_in;
  group_in.assign(group.size(), 0);
  for (std::size_t i = 0; i < group.size(); ++i) group_in[group[i]] |= in[i];
  for (std::size_t i = 0; i < group.size(); ++i) in[i] = group_in[group[i]];
}

// Marks the pieces whose box, grown by a unit, meets one of `boxes`. Returns whether any was
// not marked before. Few against few (a landscape cell's pieces and a shape's members) are
// compared pairwise; otherwise a sweep over both, as clip_near's: either list may be long.
bool bring_in_near(const std::vector<Box64>& pieces, const std::vector<Box64>& boxes,
                   ScratchVector<std::uint8_t>& in) {
  bool grew = false;
  if (pieces.size() * boxes.size() <= kFewBoxes * kFewBoxes) {
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (in[i]) continue;
      const Box64 reach = detail::grown(pieces[i], 1);
      for (const Box64& b : boxes) {
        if (!reach.overlaps(b)) continue;
        in[i] = grew = true;
        break;
      }
    }
    return grew;
  }
  ScratchVector<Box64> reach;
  ScratchVector<std::uint32_t> which;
  for (std::uint32_t i = 0; i < pieces.size(); ++i)
    if (!in[i]) {
      reach.push_back(detail::grown(pieces[i], 1));
      which.push_back(i);
    }
  detail::for_each_overlapping_pair(reach, boxes, [&](std::uint32_t k, std::uint32_t) {
    if (!in[which[k]]) in[which[k]] = grew = true;
  });
  return grew;
}

bool all_in(const ScratchVector<std::uint8_t>& in) {
  return std::find(in.begin(), in.end(), 0) == in.end();
}

// The left-out pieces, in canonical order: `pieces` (with `labels`) as they are, at `index`,
// when the input is canonical (an operation's output, the case this is for); else each ring put
// in canonical form into `own` and the list sorted.
struct LeftOut {
  const PolygonSet* pieces = nullptr;
  const RegionLabel* labels = nullptr;
  ScratchVector<std::uint32_t> index;
  PolygonSet own;
  std::vector<RegionLabel> own_labels;
  std::size_t size() const { return index.size(); }
  const Polygon& polygon(std::size_t k) const { return (*pieces)[index[k]]; }
  RegionLabel label(std::size_t k) const { return labels[index[k]]; }
};

void collect_left_out(const ValidSet& regions, std::span<const RegionLabel> labels,
                      const ScratchVector<std::uint8_t>& in, LeftOut& out) {
  for (std::uint32_t i = 0; i < in.size(); ++i)
    if (!in[i]) out.index.push_back(i);
  out.pieces = &regions.polygons();
  out.labels = labels.data();
  if (ValidSetFactory::canonical(regions)) return;
  std::vector<std::pair<Polygon, RegionLabel>> sorted;
  for (std::uint32_t i : out.index)
    sorted.emplace_back(detail::canonical_ring(regions.polygons()[i]), labels[i]);
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t k = 0; k < sorted.size(); ++k) {
    out.own.push_back(std::move(sorted[k].first));
    out.own_labels.push_back(sorted[k].second);
    out.index[k] = k;
  }
  out.pieces = &out.own;
  out.labels = out.own_labels.data();
}

// The computed regions and copies of the left-out pieces merged into one labeled set in
// canonical order (the lexicographic order of the rings: both parts are in it).
LabeledClipResult merged(LabeledClipResult computed, const LeftOut& kept) {
  PolygonSet from = std::move(computed.regions.set).release();
  const std::vector<RegionLabel>& from_labels = computed.regions.labels;
  ClipResult out;
  out.stats = computed.stats;
  std::vector<RegionLabel> out_labels;
  out.polygons.reserve(from.size() + kept.size());
  out_labels.reserve(from.size() + kept.size());
  std::size_t a = 0, b = 0;
  while (a < from.size() || b < kept.size()) {
    if (b == kept.size() || (a < from.size() && from[a] < kept.polygon(b))) {
      out.polygons.push_back(std::move(from[a]));
      out_labels.push_back(from_labels[a++]);
    } else {
      out.polygons.push_back(kept.polygon(b));
      out_labels.push_back(kept.label(b++));
    }
  }
  LabeledClipResult r;
  r.stats = out.stats;
  r.regions = {ValidSetFactory::from(std::move(out)).set, std::move(out_labels)};
  return r;
}

// relabel()'s pipeline on every piece.
LabeledClipResult overlay_all(const detail::RelabelCall& call) {
  detail::PipelineResult r = detail::run_relabel(call, nullptr, nullptr);
  return detail::relabeled_regions(r);
}

// Runs the pipeline on the groups of pieces marked in `in` and merges the left-out pieces in;
// if a segment snap rounding moved comes near a left-out piece (it could have met a vertex or
// an edge of it), runs it again on every piece instead. So an overlay costs at most two runs.
LabeledClipResult overlay_groups_in_reach(const detail::RelabelCall& call,
                                          const std::vector<Box64>& boxes,
                                          ScratchVector<std::uint8_t>& in) {
  whole_groups(groups_of(boxes, call.labels), in);
  if (all_in(in)) return overlay_all(call);
  ScratchVector<std::uint32_t> in_play;
  for (std::uint32_t i = 0; i < in.size(); ++i)
    if (in[i]) in_play.push_back(i);
  ScratchVector<Box64> moved;
  detail::PipelineResult r = detail::run_relabel(call, &in_play, &moved);
  if (bring_in_near(boxes, moved, in)) return overlay_all(call);
  LeftOut kept;
  collect_left_out(call.regions, call.labels, in, kept);
  LabeledClipResult out = merged(detail::relabeled_regions(r), kept);
  out.pieces_left_out = kept.size();
  return out;
}

}  // namespace

namespace detail {

LabeledClipResult relabel_near(const RelabelCall& call, std::span<const Box64> piece_boxes) {
  const PolygonSet& pieces = call.regions.polygons();
  ScratchVector<Box64> boxes;
  boxes.assign(piece_boxes.begin(), piece_boxes.end());
  ScratchVector<std::uint8_t> in;
  in.assign(pieces.size(), 0);
  bring_in_near(boxes, call.member_boxes(), in);
  if (!all_in(in)) return overlay_groups_in_reach(call, boxes, in);
  return overlay_all(call);  // the shape reaches every piece
}

}  // namespace detail

LabeledClipResult relabel_near(const ValidSet& regions, std::span<const RegionLabel> labels,
                               const ValidSet& shape, const Box64& window,
                               std::span<const RegionLabel> table, const ClipOptions& options) {
  detail::require_relabel_input(regions, labels, window);
  const detail::StepNear step{&shape, table, detail::shape_near_window(shape, window)};
  const PolygonSet& pieces = regions.polygons();
  ScratchVector<Box64> boxes;
  boxes.resize(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) boxes[i] = *bounding_box(pieces[i]);
  return detail::relabel_near({regions, labels, std::span(&step, 1), window, options}, boxes);
}

}  // namespace edgeland
