#pragma once
// Deltas (spatial/README.md, "Deltas, divergence and repair"): how a world moves between
// machines without a whole save file. Three kinds in one envelope, read as carefully as a save:
//   COMMAND  the edit itself, for lockstep between peers of equal algorithm version;
//   PATCH    subtrees of the tree at their paths, with the id counters after them: repairs a
//            diverged world or brings in a region, on any version;
//   CHANGES  removed ids and added polygons, for thin clients that only draw (DrawMirror).
// The tree is a Merkle tree (a node's hash is made of its children's), so two worlds find where
// they differ by comparing node hashes from the root down (DivergenceSearch) and PATCH only
// those nodes.
//
// GUARANTEES
//   * UNTRUSTED BYTES. decode_delta checks the checksum, bounds every count by the bytes left
//     before allocating for it and refuses anything malformed with a DeltaError naming the
//     byte: a decoded delta holds at most a constant times its size. A PATCH's subtrees are
//     read when applied, by the save file's hardened reader.
//   * STRONG GUARANTEE. Landscape::apply_delta builds the result apart and keeps it only when
//     every check passed: a refused delta (DeltaError, DeltaMismatch, or an edit's own error)
//     leaves the landscape bit for bit as it was.
//   * DETERMINISM. A COMMAND gives the writer's result on every compiler and platform where the
//     algorithm versions are equal (kAlgorithmVersion); a PATCH gives it on any version.
//
// Plain data and pure functions over strings: no files, no sockets (store/ and net/ carry them).
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/errors.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

// The version of the edit algorithms. It goes up whenever any edit could round differently
// (whenever the pinned hashes of tests/spatial/pinned_sequence.hpp change, which pin it beside
// them): peers of different versions may exchange PATCH and CHANGES, never COMMAND.
inline constexpr std::uint32_t kAlgorithmVersion = 1;

// Runs one edit (types.hpp Edit) on the landscape: Landscape::carve, fill, fill_empty or replace
// with the materials its map holds when the map has the kind's form (so the edit log records
// the kind), else Landscape::relabel with the map (the map is what an Edit does). The same
// errors and guarantees.
EDGELAND_EXPORT ChangeSet apply_edit(Landscape& world, const Edit& edit);

enum class DeltaKind : std::uint8_t { kCommand = 1, kPatch = 2, kChanges = 3 };

struct DeltaHeader {
  DeltaKind kind = DeltaKind::kCommand;
  std::uint32_t algorithm = kAlgorithmVersion;
  std::uint64_t world = 0;     // Landscape::world_hash()
  std::uint64_t sequence = 0;  // the edit sequence number the delta brings the world to
  std::uint64_t base = 0;      // state_hash() before
  std::uint64_t result = 0;    // state_hash() after
  friend bool operator==(const DeltaHeader&, const DeltaHeader&) = default;
};

// One subtree of a PATCH.
struct PatchEntry {
  TreePath path;
  std::uint64_t hash = 0;  // the node's hash at `path` after the patch
  // The id counter of the region holding `path` after the patch, when ids are per region and
  // the path lies below the region's node (LandscapeConfig::region_ids); else 0.
  PolygonId region_next = 0;
  std::string subtree;  // the node and all below it in the save file's tree encoding
  friend bool operator==(const PatchEntry&, const PatchEntry&) = default;
};

// A polygon as a thin client draws it.
struct DrawnPolygon {
  PolygonId id = 0;
  Material material;
  Polygon polygon;
  friend bool operator==(const DrawnPolygon&, const DrawnPolygon&) = default;
};

struct Delta {
  DeltaHeader header;
  // kCommand: the edit, or a frame batch of two or more (Landscape::apply_batch; a batch of one
  // is that edit). A COMMAND carries each edit's kind and the materials of its kind (fill: one;
  // replace: from and to; relabel: the pairs its map changes) rather than the whole map.
  std::vector<Edit> edits;
  // kPatch: the landscape's next id after the patch, and the subtrees (none: only the counter).
  PolygonId next_id = 0;
  std::vector<PatchEntry> patches;
  // kChanges: ascending ids.
  std::vector<PolygonId> removed;
  std::vector<DrawnPolygon> added;
};

// The delta's bytes (envelope, payload, checksum).
EDGELAND_EXPORT std::string encode_delta(const Delta& delta);
// Reads untrusted bytes. Throws DeltaError (what and at which byte), or for a COMMAND whose
// shape is no valid set what an edit throws for it (CoordinateOutOfRange, InvalidInput with
// operand kClip). O(size log size): a COMMAND's shape is validated.
EDGELAND_EXPORT Delta decode_delta(std::string_view bytes);

// Tree order of paths (a parent before its children), and whether `a` is `b` or lies below it:
// a PATCH's paths, sorted so, must not lie within their predecessors.
EDGELAND_EXPORT bool path_less(const TreePath& a, const TreePath& b) noexcept;
EDGELAND_EXPORT bool path_within(const TreePath& a, const TreePath& b) noexcept;

// A COMMAND: `edit` took `before` to `after` (its result), as edit number `sequence`.
EDGELAND_EXPORT Delta command_delta(const Landscape& before, const Landscape& after,
                                    std::uint64_t sequence, const Edit& edit);
// A COMMAND of a frame batch: Landscape::apply_batch(batch) took `before` to `after`. Applied,
// it runs apply_batch (a batch of one: apply_edit, and it is sent as that edit). An empty batch
// is no command: decode_delta and apply_delta refuse one.
EDGELAND_EXPORT Delta command_delta(const Landscape& before, const Landscape& after,
                                    std::uint64_t sequence, std::span<const Edit> batch);
// A PATCH of `source`'s subtrees at `paths` (each an existing node; none nesting another), as of
// edit number `sequence`; `base` is the receiver's state hash when known (0 otherwise).
// Throws InvalidPath for a path that names no node of `source`, RegionNotLoaded for one at or
// in an unloaded region.
EDGELAND_EXPORT Delta patch_delta(const Landscape& source, std::uint64_t sequence,
                                  const std::vector<TreePath>& paths, std::uint64_t base = 0);
// A CHANGES delta from an edit's change set (`after`: the landscape after it).
EDGELAND_EXPORT Delta changes_delta(const Landscape& before, const Landscape& after,
                                    std::uint64_t sequence, const ChangeSet& changes);

// The digest of one drawn polygon; a set's digest is the sum (mod 2^64) over its polygons, so it
// does not depend on their order and follows removals and additions.
EDGELAND_EXPORT std::uint64_t polygon_digest(PolygonId id, Material material,
                                             const Polygon& polygon) noexcept;

// A thin client's world: the polygons it draws, by id, kept from CHANGES deltas.
class EDGELAND_EXPORT DrawMirror {
 public:
  // Applies a CHANGES delta: every removed id must be held and every added id new (else
  // DeltaError, offset 0, and the mirror is unchanged). DeltaError also for another kind.
  void apply(const Delta& changes);
  // Sum of polygon_digest over the polygons held (Landscape::drawn_digest on the server).
  std::uint64_t digest() const noexcept { return digest_; }
  const std::map<PolygonId, DrawnPolygon>& polygons() const noexcept { return polygons_; }

 private:
  std::map<PolygonId, DrawnPolygon> polygons_;
  std::uint64_t digest_ = 0;
};

// Finds where a local landscape differs from a remote one, level by level (README, "Divergence"):
// ask the remote for the digests of questions(), pass them to answer(), until done(); then PATCH
// differing(). One round per level below `start`; each asks only for nodes whose hashes differ.
class EDGELAND_EXPORT DivergenceSearch {
 public:
  explicit DivergenceSearch(TreePath start = {});
  // Several starts (regions a client watches); none may lie within another.
  explicit DivergenceSearch(std::vector<TreePath> starts);
  const std::vector<TreePath>& questions() const noexcept { return questions_; }
  // The remote digests of questions(), in order (nullopt: no such node there), compared with
  // `local` as it is now. Throws std::invalid_argument when the count differs.
  void answer(const Landscape& local, const std::vector<std::optional<NodeDigest>>& remote);
  bool done() const noexcept { return questions_.empty(); }
  // The paths to PATCH: nodes whose hashes differ where one side is a cell, an unloaded
  // region, or of another shape.
  const std::vector<TreePath>& differing() const noexcept { return differing_; }
  std::size_t rounds() const noexcept { return rounds_; }

 private:
  std::vector<TreePath> questions_, differing_;
  std::size_t rounds_ = 0;
};

}  // namespace edgeland
