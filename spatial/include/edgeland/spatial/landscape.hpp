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
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
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

namespace edgeland {

// 0 is empty space; 1..255 are solid materials.
using Material = std::uint8_t;
inline constexpr Material kEmpty = 0;
inline constexpr std::size_t kMaterialCount = 256;

using PolygonId = std::uint64_t;

enum class TreeKind : std::uint8_t {
  kQuadtree,  // four children, cut at both midpoint lines
  kKdTree,    // two children, cut at the midpoint of the longer side (x on ties)
};

struct LandscapeConfig {
  TreeKind tree = TreeKind::kQuadtree;
  // A cell whose polygons have more edges than this splits (unless both its sides are at most
  // min_cell_size); siblings whose cells together have at most merge_below edges merge back.
  // merge_below < edge_cap is the hysteresis that keeps a digger going back and forth over a
  // cell line from splitting and merging on every edit. edge_cap >= 32: a cell crossed by a
  // boundary or two must not split (a long slanted boundary would split every cell along it).
  std::uint32_t edge_cap = 64;
  std::uint32_t merge_below = 24;
  std::int64_t min_cell_size = 16;
  // >= 0: a uniform grid (thesis 4.4): the tree is built to this depth at once and never
  // splits or merges. -1: adaptive.
  int grid_depth = -1;
};

// Limits on what one landscape may hold; an edit that would pass one throws LimitExceeded and
// changes nothing.
struct LandscapeLimits {
  std::size_t max_vertices = std::size_t{1} << 28;        // all polygons together
  std::size_t max_shape_vertices = std::size_t{1} << 24;  // one edit's shape
};

// Every landscape error is an edgeland::Error; each keeps its data in fields.
class EDGELAND_EXPORT LandscapeError : public Error {
 public:
  using Error::Error;
};

// The world box or the configuration is unusable (inverted or degenerate box, box beyond the
// coordinate bound, edge_cap < 32, merge_below >= edge_cap, min_cell_size < 1, grid_depth
// outside -1..10).
// `setting` names the rule broken; `world` is the world box given and `config` the
// configuration, whichever of them is wrong.
class EDGELAND_EXPORT InvalidConfig : public LandscapeError {
 public:
  enum class Setting : std::uint8_t {
    kWorldOutOfRange,  // a corner beyond kCoordBound
    kWorldEmpty,       // width or height not positive (inverted or degenerate)
    kEdgeCap,          // edge_cap below 32
    kMergeBelow,       // merge_below not below edge_cap
    kMinCellSize,      // min_cell_size below 1
    kGridDepth,        // grid_depth outside -1..10
    kTree,             // not a TreeKind
  };
  InvalidConfig(Setting setting, const Box64& world, const LandscapeConfig& config);
  Setting setting;
  Box64 world;
  LandscapeConfig config;
};

class EDGELAND_EXPORT LimitExceeded : public LandscapeError {
 public:
  enum class Limit : std::uint8_t { kVertices, kShapeVertices };
  LimitExceeded(Limit limit, std::size_t maximum, std::size_t requested);
  Limit limit;
  std::size_t maximum;
  std::size_t requested;
};

// A checked-mode invariant failed: a bug in edgeland. `state` is the landscape before the
// edit as a save file (Landscape::load reads it), `log` an edit log that replays to it (exactly
// when the landscape recorded its log from the start, else approximately: the world and one
// fill per material) followed by the failing edit.
class EDGELAND_EXPORT LandscapeInternalError : public LandscapeError {
 public:
  LandscapeInternalError(const std::string& what, std::string state, std::string log);
  std::string state;
  std::string log;
};

// A save file could not be read: truncated, corrupt, of another version, or describing a
// world that breaks an invariant. `offset` is where reading stopped (bytes from the start).
class EDGELAND_EXPORT LoadError : public LandscapeError {
 public:
  LoadError(const std::string& what, std::size_t offset);
  std::size_t offset;
};

// One polygon of the landscape as a query or a change set shows it.
struct PolygonView {
  PolygonId id = 0;
  Material material = kEmpty;
  const Polygon* polygon = nullptr;  // valid while the landscape (or change set) holding it lives
  Box64 cell;                        // the closed box of its cell
};

// One cell of the tree.
struct CellView {
  Box64 box;
  std::uint32_t depth = 0;
  std::size_t polygons = 0, vertices = 0;
};

// What an edit changed.
struct ChangeSet {
  std::vector<PolygonId> removed;  // ids that no longer exist, ascending
  struct Added {
    PolygonId id;
    Material material;
    Polygon polygon;
    Box64 cell;
  };
  std::vector<Added> added;  // by ascending id
  std::vector<Box64> cells;  // the cells whose content is new (leaves after the edit)
  // Twice the change of area per material (exact; sums to 0 over all materials including 0).
  std::vector<std::pair<Material, Int128>> twice_area_delta;
  bool empty() const noexcept { return removed.empty() && added.empty(); }
};

// The material profile along a segment: a place where the material changes.
struct MaterialCrossing {
  Fraction t;           // at from + t (to - from), 0 <= t <= 1 (exact)
  RationalPoint point;  // the same point, exactly
  Point64 rounded;      // round_to_grid(point): the kernel's one rounding
  Material before = kEmpty, after = kEmpty;
  PolygonId polygon = 0;   // the polygon entered (after != 0), else the one left
  std::uint32_t edge = 0;  // its edge crossed: from vertex edge to vertex edge + 1
  Point64 normal;          // that edge's outward normal (dy, -dx): not normalised, exact
};

// What check() found; empty when every invariant holds.
struct LandscapeReport {
  std::vector<std::string> problems;  // one line each, e.g. "cell (0 0 64 64): polygon 3 outside"
  bool ok() const noexcept { return problems.empty(); }
};

struct LandscapeStats {
  std::size_t polygons = 0, vertices = 0, cells = 0, depth = 0;
  std::size_t bytes = 0;  // memory of the cells and nodes this landscape holds (shared or not)
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
  ChangeSet carve(const PolygonSet& shape);
  ChangeSet fill(const PolygonSet& shape, Material material);
  ChangeSet fill_empty(const PolygonSet& shape, Material material);
  ChangeSet replace(const PolygonSet& shape, Material from, Material to);

  // --- queries -------------------------------------------------------------------------------
  // The material at p by the half-open rule: that of the face holding p + eps (1, eps), so a
  // point on a boundary has the material to its east (north-east on a horizontal edge), as a
  // pixel holds the points that round to it. Outside the world: kEmpty. O(depth + cell).
  Material material_at(Point64 p) const;
  // Every material change along the segment from -> to, in order (the segment moved by
  // eps (1, eps), as material_at looks at points: segment_crossings.hpp). A change at t = 0
  // is one from the material just behind `from`. Cell lines and other edges between two pieces
  // of one material are no change. from and to must be in range.
  std::vector<MaterialCrossing> crossings(Point64 from, Point64 to) const;
  // The first place the ray from -> to enters a solid material other than the one it is in
  // (back faces culled, thesis 2.4.2): a ray starting in empty space hits the first surface; one
  // starting inside rock hits only a different material, never the way out.
  std::optional<MaterialCrossing> raycast(Point64 from, Point64 to) const;
  // The solid materials whose interiors meet the shape's interior (touching is not
  // overlapping), ascending; empty when none does. The box form is the fast path for
  // character-sized boxes: its corners must be in range (else CoordinateOutOfRange, operand
  // kQuery, vertex kNone, `where` the corner); a box of zero width or height, or an inverted
  // one (min.x > max.x or min.y > max.y), has no interior and overlaps nothing: an empty
  // answer, not an error (unlike clip_to_box, which throws InvalidBox).
  std::vector<Material> overlaps(const Box64& box) const;
  std::vector<Material> overlaps(const ValidSet& shape) const;
  // Calls visit for every polygon whose bounding box meets the closed box; stop by returning
  // false. Order: cell by cell in tree order, canonical order within a cell. Only compares
  // coordinates, so any box is accepted; an inverted box holds no point and meets nothing.
  void polygons_in(const Box64& box, const std::function<bool(const PolygonView&)>& visit) const;
  // Calls visit for every cell whose closed box meets the closed box (empty cells included),
  // in tree order; stop by returning false. Any box; an inverted one meets nothing.
  void cells_in(const Box64& box, const std::function<bool(const CellView&)>& visit) const;
  // Twice the area of a material (exact), over the whole world (material 0: the empty area).
  Int128 twice_area(Material m) const;
  LandscapeStats stats() const;

  const Box64& world() const noexcept { return world_; }
  const LandscapeConfig& config() const noexcept { return config_; }
  const LandscapeLimits& limits() const noexcept { return limits_; }

  // --- state -----------------------------------------------------------------------------
  // FNV-style 64-bit hash of the whole state (world, configuration, tree, every polygon with
  // its id and material, the next id): equal states, equal hashes. O(1) (kept in the nodes).
  std::uint64_t state_hash() const noexcept;
  // Verifies every invariant of spatial/README.md over the whole landscape; the report lists
  // what broke. O(N log N).
  LandscapeReport check() const;
  void set_checked(bool on) noexcept { checked_ = on; }
  bool checked() const noexcept { return checked_; }
  // Recording: every successful edit is appended to log() as a line of the landscape edit log
  // format (README.md "Landscape edit logs"). Started on a landscape that was never edited, the
  // log replays to the same state bit for bit. Started later, it begins with the current state
  // (a `world` line, then one fill per material): that replays to the same regions, but the
  // replayed world has its own cells, so later edits may round differently there (within the
  // accuracy contract) and the state hashes differ.
  void start_log();
  void stop_log() noexcept { logging_ = false; }
  bool logging() const noexcept { return logging_; }
  // The recorded lines, each ending in '\n'. O(length).
  std::string log() const;

  // Versioned binary, little-endian, with a checksum (spatial/README.md). load() validates
  // everything (a save file is untrusted) and throws LoadError; it gives the same state_hash.
  void save(std::ostream& out) const;
  static Landscape load(std::istream& in, const LandscapeLimits& limits = {});

  struct Node;     // the tree (spatial/src/node.hpp)
  struct LogLine;  // the recorded log, a persistent list shared by copies
  using AreaTable = std::array<Int128, kMaterialCount>;

 private:
  Landscape() = default;
  friend class LandscapeEditor;
  friend class LandscapeLoader;
  friend struct LandscapeAccess;

  Box64 world_;
  LandscapeConfig config_;
  LandscapeLimits limits_;
  std::shared_ptr<const Node> root_;
  std::shared_ptr<const AreaTable> areas_;  // twice the area of every solid material
  PolygonId next_id_ = 1;
  std::uint64_t edits_ = 0;  // successful edits since construction (or load)
  Material initial_fill_ = kEmpty;
  bool checked_ = false;
  bool logging_ = false;
  std::shared_ptr<const LogLine> log_;  // the last line recorded
};

}  // namespace edgeland
