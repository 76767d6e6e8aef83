#pragma once
// The landscape (thesis chapter 4; spatial/README.md): a world of integer polygons of several
// materials, kept in the cells of a PR tree, carved, filled and queried in real time, forever.
//
// GUARANTEES
//   * VALID. All polygons of all materials together form a valid polygon set (kernel
//     validate.hpp) at all times: strictly simple, counter-clockwise, hole-free, pairwise
//     disjoint interiors. Every polygon lies inside its cell's closed box: polygons are cut at
//     the cell lines (thesis 4.5.2), and pieces on the two sides of a line meet exactly.
//   * STRONG GUARANTEE. An edit that throws (an invalid shape, coordinates out of range, a
//     resource limit, ...) leaves the landscape bit for bit as it was (state_hash unchanged).
//   * ACCURACY. An edit moves material boundaries only by the one snap rounding of clip.hpp's
//     accuracy contract, applied to the shape cut to each cell in one arrangement; cells split
//     when too crowded round once more where the new cell lines cut a boundary.
//   * CANONICAL CELLS. A cell's content is the canonical decomposition of its material regions
//     (relabel.hpp): the same regions give the same polygons whatever edits produced them.
//   * IDS. A polygon keeps its id as long as it is unchanged (same vertices, same material),
//     also when an edit splits or merges the cells around it and it ends up in another cell.
//     An untouched region can still come out as other polygons: the canonical decomposition can
//     cut it differently (a new cell line across it, a bridge to a new hole through it), and
//     those are new polygons with new ids. Ids are never reused; fresh ones go only to polygons
//     the edit leaves in the landscape. An edit's change set names every polygon removed and
//     added, so a game rebuilds exactly the colliders and meshes of what changed.
//   * DETERMINISM. Integer arithmetic only: the same edits give the same state and the same
//     state_hash() on every compiler and optimisation level.
//   * SNAPSHOTS. Copying a Landscape costs O(1): the tree is persistent and shared between
//     copies; an edit copies only the cells it changes and the path above them.
//   * CHECKED MODE (set_checked): every edit re-verifies every invariant of spatial/README.md
//     on the cells it made and throws LandscapeInternalError (carrying the state and a
//     replayable log) instead of ever keeping a wrong world.
//
// THREADS. A Landscape is a value: distinct objects (copies included) may be used from different
// threads; one object must not be modified while used elsewhere. No threads, files or printing
// inside; save/load take the caller's streams.
//
// HEADERS. This is the front end and the umbrella: it includes material.hpp (Material),
// types.hpp (the configuration, views, change sets, crossings, reports) and errors.hpp (the
// landscape's errors), which code that only handles those types can include alone.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/spatial/errors.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

struct Delta;       // delta.hpp
struct PatchEntry;  // delta.hpp

namespace detail {

struct Node;     // the tree (spatial/src/node.hpp)
struct LogLine;  // the recorded log, a persistent list shared by copies (spatial/src/edit_log.hpp)
using AreaTable = std::array<Int128, kMaterialCount>;

struct EditTable;  // an edit's material -> material table (spatial/src/edit.hpp)
struct EditStep;   // a shape and its table: one step of an edit or a batch (edit.hpp)

// A landscape's whole state, private to Landscape: spatial/src's stages take it as an argument
// from the Landscape's members. An edit builds the next state from it and Landscape::apply
// commits that by one assignment, so a throw leaves it as it was.
struct LandscapeState {
  Box64 world;
  LandscapeConfig config;
  LandscapeLimits limits;
  std::shared_ptr<const Node> root;
  std::shared_ptr<const AreaTable> areas;  // twice the area of every solid material
  PolygonId next_id = 1;
  std::uint64_t edits = 0;  // successful edits since construction (or load)
  Material initial_fill = kEmpty;
  bool checked = false;
  bool logging = false;
  std::shared_ptr<const LogLine> log;  // the last line recorded
};

}  // namespace detail

class EDGELAND_EXPORT Landscape {
 public:
  // The world box must lie within the coordinate bound with positive width and height; the
  // world starts empty, or filled with `fill`. Throws InvalidConfig.
  explicit Landscape(const Box64& world, Material fill = kEmpty, const LandscapeConfig& config = {},
                     const LandscapeLimits& limits = {});

  // --- edits: any valid polygon set as the shape; parts past the world box are cut off -----
  // Throws CoordinateOutOfRange (a coordinate beyond kCoordBound), InvalidInput (any other
  // violation of validate(); operand kClip), LimitExceeded, LandscapeInternalError.
  ChangeSet carve(const ValidSet& shape);                          // everything under it: empty
  ChangeSet fill(const ValidSet& shape, Material material);        // everything under it: material
  ChangeSet fill_empty(const ValidSet& shape, Material material);  // only where empty
  ChangeSet replace(const ValidSet& shape, Material from, Material to);
  // The general edit: inside the shape every material m becomes map[m] (material.hpp), in one
  // pass over the touched cells, where the same change as several replace() calls would take
  // one pass each (and a swap of two materials, none of them alone). The four edits above are
  // relabel() with their maps; the same guarantees and errors.
  ChangeSet relabel(const ValidSet& shape, const MaterialMap& map);
  ChangeSet carve(const PolygonSet& shape);
  ChangeSet fill(const PolygonSet& shape, Material material);
  ChangeSet fill_empty(const PolygonSet& shape, Material material);
  ChangeSet replace(const PolygonSet& shape, Material from, Material to);
  ChangeSet relabel(const PolygonSet& shape, const MaterialMap& map);
  // A frame's edits (types.hpp Edit) applied in order as ONE edit: one overlay per touched cell
  // (of kMaxBatchSteps edits at a time: relabel.hpp), rounded once, and one change set. Inside
  // the cell a point of material m ends as m passed through the map of every edit whose shape
  // holds it, in order: the materials applying the edits one by one would give before rounding.
  // Rounding once where the edits one by one round after each, the two results differ only
  // near the shapes' boundaries, within the rounding bound of spatial/README.md ("Batches"); the
  // one-by-one edits are still there (apply_edit, or carve ... relabel) for a game that wants
  // each rounded. A batch of one is that edit (the same result and log line); an empty batch
  // changes nothing. Deterministic, valid, the strong guarantee and checked mode as every edit;
  // recorded as one `batch` line. Throws what an edit throws (LimitExceeded: any shape, or the
  // landscape after the batch, past its limits).
  ChangeSet apply_batch(std::span<const Edit> edits);

  // --- queries -------------------------------------------------------------------------------
  // Queries check their coordinates as edits check their shapes: a point, a segment end or a
  // box corner beyond kCoordBound throws CoordinateOutOfRange (operand kQuery; `vertex` is the
  // argument's index, 0 for p, from or a box's min and 1 for to or a box's max, and the
  // message names it). An inverted box is no error: it holds no point.
  //
  // The material at p by the half-open rule: that of the face holding p + eps (1, eps), so a
  // point on a boundary has the material to its east (north-east on a horizontal edge), as a
  // pixel holds the points that round to it. Outside the world: kEmpty. O(depth + cell).
  Material material_at(Point64 p) const;
  // Every material change along the segment from -> to, in order (the segment moved by
  // eps (1, eps), as material_at looks at points: segment_crossings.hpp). A change at t = 0
  // is one from the material just behind `from`. Cell lines and other edges between two pieces
  // of one material are no change, and neither is the world box's border: where the segment
  // enters or leaves the world, nothing is reported (a ray starting on the world's edge sees
  // the terrain, not the edge; before its first change a ray from outside is in the material
  // where it enters).
  std::vector<MaterialCrossing> crossings(Point64 from, Point64 to) const;
  // The first place the ray from -> to enters a solid material other than the one it is in
  // (back faces culled, thesis 2.4.2): a ray starting in empty space hits the first surface; one
  // starting inside rock hits only a different material, never the way out. The world's border
  // is no surface (as for crossings).
  std::optional<MaterialCrossing> raycast(Point64 from, Point64 to) const;
  // The solid materials whose interiors meet the shape's interior (touching is not
  // overlapping), ascending; empty when none does. The box form is the fast path for
  // character-sized boxes; a box of zero width or height, or an inverted one (min.x > max.x or
  // min.y > max.y), has no interior and overlaps nothing: an empty answer, not an error
  // (unlike clip_to_box, which throws InvalidBox).
  std::vector<Material> overlaps(const Box64& box) const;
  std::vector<Material> overlaps(const ValidSet& shape) const;
  // Calls visit for every polygon whose bounding box meets the closed box; stop by returning
  // false. Order: cell by cell in tree order, canonical order within a cell. A view shares its
  // polygon's cell, so its polygon stays valid as long as the view lives (types.hpp).
  void polygons_in(const Box64& box, const std::function<bool(const PolygonView&)>& visit) const;
  // Calls visit for every cell whose closed box meets the closed box (empty cells included),
  // in tree order; stop by returning false.
  void cells_in(const Box64& box, const std::function<bool(const CellView&)>& visit) const;
  // Twice the area of a material (exact), over the whole world (material 0: the empty area).
  Int128 twice_area(Material m) const;
  LandscapeStats stats() const;

  const Box64& world() const noexcept { return s_.world; }
  const LandscapeConfig& config() const noexcept { return s_.config; }
  const LandscapeLimits& limits() const noexcept { return s_.limits; }
  // The id the next new polygon takes (ids are never reused: every id in the world is below it).
  PolygonId next_id() const noexcept { return s_.next_id; }

  // --- state -----------------------------------------------------------------------------
  // FNV-style 64-bit hash of the whole state (world, configuration, tree, every polygon with
  // its id and material, the next id): equal states, equal hashes. O(1) (kept in the nodes).
  std::uint64_t state_hash() const noexcept;
  // Verifies every invariant of spatial/README.md over the whole landscape; the report lists
  // what broke. O(N log N).
  LandscapeReport check() const;
  void set_checked(bool on) noexcept { s_.checked = on; }
  bool checked() const noexcept { return s_.checked; }
  // Recording: every successful edit is appended to log() as a line of the landscape edit log
  // format (README.md "Landscape edit logs"). Started on a landscape that was never edited, the
  // log replays to the same state bit for bit. Started later, it begins with the current state
  // (a `world` line, then one fill per material): that replays to the same regions, but the
  // replayed world has its own cells, so later edits may round differently there (within the
  // accuracy contract) and the state hashes differ.
  void start_log();
  void stop_log() noexcept { s_.logging = false; }
  bool logging() const noexcept { return s_.logging; }
  // The recorded lines, each ending in '\n'. O(length).
  std::string log() const;

  // Versioned binary, little-endian, with a checksum (spatial/README.md). load() gives the same
  // state_hash. A save file is untrusted, and anyone can recompute its checksum: load() checks
  // every invariant of spatial/README.md on each node as it reads it, so a bad file is refused
  // before the work it asks for is done; its peak memory is about twice the file (a refused
  // file) plus the world it returns. Throws LoadError (what and at which byte; memory running out
  // during a load is one too), or LimitExceeded when the world would pass `limits` (the file's
  // own bytes are bounded by them first). O(n log n) for n vertices: each cell is validated once.
  void save(std::ostream& out) const;
  static Landscape load(std::istream& in, const LandscapeLimits& limits = {});

  // --- deltas and divergence (delta.hpp; spatial/README.md "Deltas, divergence and repair") --
  // The hash of the world box and the configuration: a delta names the world it belongs to.
  std::uint64_t world_hash() const noexcept;
  // The node at `path`: its box, its hash and its children's hashes; nullopt when the path names
  // no node. O(depth).
  std::optional<NodeDigest> node_digest(const TreePath& path) const;
  // The subtree at `path` as a PATCH carries it (patch_delta). Throws InvalidPath. O(subtree).
  PatchEntry patch_entry(const TreePath& path) const;
  // Applies a COMMAND (the edit, as apply_edit) or a PATCH (its subtrees, ids and counters),
  // after checking that it belongs to this world (DeltaMismatch kWorld; a COMMAND also kAlgorithm)
  // and, as `checks` asks, that this landscape is its base (kBase) and that the result is its
  // result (kResult). Returns what changed, as an edit does. Throws DeltaError (a CHANGES delta,
  // or a PATCH whose subtree breaks a rule of this world: the offset is within that subtree),
  // DeltaMismatch, LimitExceeded, or what the COMMAND's edit throws; then the landscape is as
  // it was. O(edit) for a COMMAND; O(patched subtrees + the polygons outside them) for a PATCH,
  // which checks its ids against every other polygon.
  ChangeSet apply_delta(const Delta& delta, const DeltaChecks& checks = {});
  // Sum of polygon_digest (delta.hpp) over every polygon below `path`: what a thin client's
  // DrawMirror holding that part of the world has as its digest. Throws InvalidPath. O(subtree).
  std::uint64_t drawn_digest(const TreePath& path = {}) const;

 private:
  explicit Landscape(detail::LandscapeState state) : s_(std::move(state)) {}
  // The one edit driver (spatial/README.md, "An edit"): builds the next state from s_ with the
  // steps (an edit's shape and table, or a batch's), appends `log_line` to the log when
  // recording, then commits.
  ChangeSet apply(std::span<const detail::EditStep> steps,
                  const std::function<std::string()>& log_line);

  detail::LandscapeState s_;
};

}  // namespace edgeland
