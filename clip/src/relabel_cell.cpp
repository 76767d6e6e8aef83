// relabel_cell() (relabel.hpp): a landscape cell's overlay, the quick cases first
// (relabel_quick.hpp), then relabel_near()'s arrangement, small (small_overlay.hpp) or general.
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "relabel_pipeline.hpp"
#include "relabel_quick.hpp"
#include "small_overlay.hpp"

namespace edgeland {
namespace {

using detail::ScratchVector;

std::size_t edges_of(const PolygonSet& set, std::span<const std::uint32_t> members) {
  std::size_t n = 0;
  for (std::uint32_t m : members) n += set[m].size();
  return n;
}

// Whether the arrangement can be the small overlay's: every region edge, the near members' and
// the window's (an upper bound on what relabel_near() puts in).
bool small_enough(const LabeledSet& cell, const ValidSet& shape,
                  const detail::ShapeNearWindow& near) {
  std::size_t n = 4 + edges_of(shape.polygons(), near.members);
  for (const Polygon& p : cell.set.polygons()) n += p.size();
  return n <= detail::kSmallOverlayUpTo;
}

// Checked mode: the overlay is relabel()'s (clip/README.md, "The small overlay" and "Regions
// the shape cannot reach", say why it is).
void require_relabels(const LabeledSet& cell, const ValidSet& shape, const Box64& window,
                      std::span<const RegionLabel> table, const LabeledSet& got) {
  const LabeledClipResult full =
      relabel(cell.set, cell.labels, shape, window, table, {.checked = true});
  // Not reached by tests: the two agree (an internal error otherwise).
  if (!same_content(full.regions, got))
    throw InternalError("relabel_cell differs from relabel", to_wkt(cell.set.polygons()),
                        to_wkt(shape.polygons()));
}

}  // namespace

CellOverlayResult relabel_cell(const LabeledSet& cell, const ValidSet& shape, const Box64& window,
                               std::span<const RegionLabel> table, const ClipOptions& options) {
  detail::require_relabel_input(cell.set, cell.labels, window);
  const detail::ShapeNearWindow near = detail::shape_near_window(shape, window);
  const PolygonSet& pieces = cell.set.polygons();
  ScratchVector<Box64> boxes;
  boxes.resize(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) boxes[i] = *bounding_box(pieces[i]);
  CellOverlayResult out;
  if (auto quick = detail::quick_overlay({cell, boxes, window}, shape, near, table)) {
    out.content = std::move(quick->content);
    return out;
  }
  const bool small = small_enough(cell, shape, near);
  out.path = small ? CellOverlayPath::kSmall : CellOverlayPath::kGeneral;
  LabeledClipResult r = detail::relabel_near(
      {cell.set, cell.labels, shape, near, window, table, options, small}, boxes);
  if (options.checked) require_relabels(cell, shape, window, table, r.regions);
  out.pieces_left_out = r.pieces_left_out;
  if (!same_content(r.regions, cell)) out.content = std::move(r.regions);
  return out;
}

}  // namespace edgeland
