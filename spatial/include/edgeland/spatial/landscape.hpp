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
// landscape's errors), which code that only handles those types can include alone, and
// landscape_state.hpp (the private state, detail::LandscapeState).
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
#include "edgeland/spatial/landscape_state.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

struct Delta;       // delta.hpp
struct PatchEntry;  // delta.hpp

namespace detail {
struct EditTable;   // an edit's material -> material table (spatial/src/edit.hpp)
struct EditResult;  // what an edit builds (spatial/src/edit.hpp)
}  // namespace detail

// One cell's polygons as arrays, for code that reads whole cells (the game layer): what
// polygons_in hands out one view at a time, without a visitor or a reference count per polygon.
// It shares the cell, so the arrays stay valid as long as it lives, whatever happens to the
// landscape meanwhile (as PolygonView). Canonical order within the cell.
class EDGELAND_EXPORT CellContents {
 public:
  const Box64& box() const noexcept;
  std::size_t size() const noexcept;
  std::span<const Polygon> polygons() const noexcept;
  std::span<const PolygonId> ids() const noexcept;
  std::span<const Box64> bounds() const noexcept;  // each polygon's bounding box
  Material material(std::size_t i) const noexcept;
  // The polygons as the valid set they are (clip's subset() takes some of them, join() puts
  // several cells' together, neither validating again).
  const ValidSet& set() const noexcept;

 private:
  friend class Landscape;
  explicit CellContents(std::shared_ptr<const detail::Node> cell) : cell_(std::move(cell)) {}
  std::shared_ptr<const detail::Node> cell_;
};

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
  // Removes these polygons (each at most once): a carve of exactly their region, recorded as one
  // in the log. Its edges are the landscape's own, so it meets no crossing, rounds nothing and
  // leaves every other polygon's region as it was; no shape is validated (each cell's polygons
  // are a valid set). What a game detaching debris calls. Throws UnknownPolygon (nothing
  // changed), LimitExceeded, LandscapeInternalError, and RegionNotLoaded for a polygon named in
  // an unloaded region (under UnloadedRegions::kSkip such names are left out, as an edit leaves
  // a stub). O(depth per polygon + the cells' overlays).
  ChangeSet remove(std::span<const PolygonRef> polygons);
  // A frame's edits (types.hpp Edit), applied in order as ONE edit: in every cell some of their
  // shapes reach, one overlay of the cell with all of those shapes (clip's relabel_cell of
  // several steps, relabel.hpp), rounded once; one change set, one log line (`batch`), one
  // edit counted. Inside a touched cell a point of material m ends as m passed through the map
  // of every edit whose shape holds it, in order: what the edits one by one give before
  // rounding. The one-by-one edits round after each edit, so the two results differ near the
  // shapes' boundaries, within the rounding bound spatial/README.md ("Frame batches") states
  // and tests; both stay available (apply_edit, carve ... relabel, for a game that wants each
  // edit rounded on its own). A batch of one is apply_edit of that edit (the same state, hash
  // and log line); an empty batch changes nothing and counts no edit. Deterministic, valid,
  // the strong guarantee and checked mode as every edit. Throws what an edit throws
  // (LimitExceeded for any shape, or the landscape after the batch, past its limits).
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
  // The cell whose box is exactly `box`, if the landscape has one. O(depth). (A box that is not a
  // cell's, an inner node's included, gives nullopt: no error.) Throws RegionNotLoaded when the
  // box lies in an unloaded region.
  std::optional<CellContents> cell(const Box64& box) const;
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
  // Applies a COMMAND (the edit, as apply_edit; a batch, as apply_batch) or a PATCH (its subtrees,
  // ids and counters), after checking that it belongs to this world (DeltaMismatch kWorld; a
  // COMMAND also kAlgorithm) and, as `checks` asks, that this landscape is its base (kBase) and
  // that the result is its result (kResult). Returns what changed, as an edit does. Throws
  // DeltaError (a CHANGES delta, or a PATCH whose subtree breaks a rule of this world: the offset
  // is within that subtree), DeltaMismatch, LimitExceeded, or what the COMMAND's edit throws; then
  // the landscape is as it was. O(edit) for a COMMAND; O(patched subtrees + the polygons outside
  // them) for a PATCH, which checks its ids against every other polygon.
  ChangeSet apply_delta(const Delta& delta, const DeltaChecks& checks = {});
  // Sum of polygon_digest (delta.hpp) over every polygon below `path`: what a thin client's
  // DrawMirror holding that part of the world has as its digest. Throws InvalidPath. O(subtree).
  std::uint64_t drawn_digest(const TreePath& path = {}) const;

  // --- regions (LandscapeConfig::region_depth; spatial/README.md "Regions") ---------------
  // A region is a node at the region depth. An unloaded region is a stub that keeps its hash,
  // areas and counts: state_hash(), twice_area() and stats() stay exact, and an edit or a query
  // that reaches it throws RegionNotLoaded (an edit changes nothing then), as save() does.
  //
  // Every region's path, in tree order (none without regions). O(regions).
  std::vector<TreePath> region_paths() const;
  // The regions whose box interior meets `box`: those an edit whose shape has this bounding box
  // reaches. O(regions met x depth).
  std::vector<TreePath> regions_meeting(const Box64& box) const;
  // A region's hash, counts, areas and ids, loaded or not. Throws InvalidPath (no region there).
  // O(region) when loaded.
  RegionSummary region_summary(const TreePath& path) const;
  bool region_loaded(const TreePath& path) const;
  // The memory of a loaded region's nodes (stats().bytes of it); a stub's own for an unloaded
  // one. Throws InvalidPath. O(region).
  std::size_t region_bytes(const TreePath& path) const;
  // Writes the region as a region record (its summary and its subtree, with a checksum).
  // Throws InvalidPath, RegionNotLoaded. O(region).
  void save_region(const TreePath& path, std::ostream& out) const;
  // Writes the region's summary alone, as a record without its content (loaded or not): what
  // another world needs to hold it as a stub (from_regions with read_region_summary). Throws
  // InvalidPath. O(region) when loaded.
  void save_region_summary(const TreePath& path, std::ostream& out) const;
  // Replaces the region by its stub; nothing else changes (not the state hash). Throws
  // InvalidPath. O(region) (its summary).
  void unload_region(const TreePath& path);
  // Reads a region record into its stub: the record must be of this world, at a stub whose
  // hash and summary it has, and is read as load() reads a file (every node checked, counts
  // against the limits). Throws LoadError (offset within the record) or LimitExceeded, and then
  // changes nothing. O(region).
  void load_region(std::istream& in);
  // What an edit does where it reaches an unloaded region: refuse (the default) or skip.
  void set_unloaded_policy(UnloadedRegions policy) noexcept { s_.unloaded = policy; }
  UnloadedRegions unloaded_policy() const noexcept { return s_.unloaded; }
  // A world of stubs only, from the summaries of its regions (each region exactly once, of this
  // world): what a store opens before it loads any region. `next_id` is the landscape's next id
  // (1 with region_ids). Throws InvalidConfig (regions off or a bad configuration), LoadError
  // (a region missing, twice, of another world, or with a counter outside its id space; offset 0)
  // or LimitExceeded.
  static Landscape from_regions(const Box64& world, const LandscapeConfig& config,
                                PolygonId next_id, const std::vector<RegionSummary>& regions,
                                const LandscapeLimits& limits = {});
  // The summary at the head of a region record (or of a summary record), its checksum checked.
  // Throws LoadError.
  static RegionSummary read_region_summary(std::istream& in);

 private:
  explicit Landscape(detail::LandscapeState state) : s_(std::move(state)) {}
  // The one edit driver (spatial/README.md, "An edit"): builds the next state from s_ with the
  // shape and the table, appends `log_line` to the log when recording, then commits.
  ChangeSet apply(const ValidSet& shape, const detail::EditTable& table,
                  const std::function<std::string()>& log_line);
  // The same for any way of building the next state (Landscape::remove's cut shape, a batch).
  ChangeSet apply(const std::function<detail::EditResult()>& build,
                  const std::function<std::string()>& log_line);

  detail::LandscapeState s_;
};

}  // namespace edgeland
