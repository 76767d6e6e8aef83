// The game layer's fuzz target (issues 26, 35): an edit sequence decoded as edit_sequence decodes
// it (landscape_decoding.hpp), with a material table and a border mode, and after every edit the
// game layer checked against references that share no code with it (the tests' oracles:
// tests/support/surface_oracle, island_oracle, chain_rules.hpp; tests/support/piece_checks): the
// standalone trackers edit by edit, and a GameDriver taking the same edits in frames (the input
// says where a frame ends), its updates mirrored and checked after every frame.
// Declared in decoders.hpp.
#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "chain_rules.hpp"
#include "decoders.hpp"
#include "edgeland/game/game_driver.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/game/surface_tracker.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/validate.hpp"
#include "island_oracle.hpp"
#include "landscape_decoding.hpp"
#include "piece_checks.hpp"
#include "surface_oracle.hpp"

namespace edgeland::fuzz {
namespace {

using Mirror = std::map<ChainId, SurfaceChain>;
using test::IdSet;

// Materials 1..4 (the ones the edits use): mostly solid, now and then anchored; the border a
// wall or not.
SurfaceOptions decode_options(Provider& in) {
  SurfaceOptions o;
  for (int m = 1; m <= 4; ++m) {
    o.materials.set_solid(m, in.ConsumeIntegralInRange(0, 3) != 0);
    o.materials.set_anchored(m, in.ConsumeIntegralInRange(0, 3) == 0);
  }
  o.border_wall = in.ConsumeBool();
  return o;
}

std::string options_text(const SurfaceOptions& o) {
  std::string solid, anchored;
  for (int m = 1; m <= 4; ++m) {
    if (o.materials.is_solid(m)) solid += std::to_string(m) + " ";
    if (o.materials.anchored[m]) anchored += std::to_string(m) + " ";
  }
  return "solid {" + solid + "} anchored {" + anchored + "} border wall " +
         (o.border_wall ? "on" : "off");
}

bool chain_less(const SurfaceChain& l, const SurfaceChain& r) {
  const auto key = [](const SurfaceChain& c) {
    return std::tie(c.cell.min, c.cell.max, c.points, c.materials, c.closed, c.ghost_prev,
                    c.ghost_next);
  };
  return key(l) < key(r);
}

std::vector<SurfaceChain> sorted(std::vector<SurfaceChain> v) {
  std::sort(v.begin(), v.end(), chain_less);
  return v;
}

// The game layer's state beside the landscape, and the checks after each change set.
class GameCheck {
 public:
  GameCheck(const Landscape& l, const SurfaceOptions& options)
      : options_(options),
        tracker_(l, options),
        mirror_(tracker_.chains()),
        islands_(l, options.materials),
        known_(test::islands_brute(l, options.materials)) {}

  // The chains of the start, against the references.
  std::optional<std::string> start(const Landscape& l) { return surface(l); }

  // Every check after one change set; `fresh` receives the islands the update reported.
  std::optional<std::string> after(const Landscape& l, const ChangeSet& changes,
                                   std::vector<Island>& fresh) {
    if (auto e = chains(l, changes)) return e;
    if (auto e = meshes(changes)) return e;
    if (auto e = pieces(changes)) return e;
    return islands(l, changes, fresh);
  }

 private:
  // The mirror kept from the tracker's updates equals a full export, which keeps the chain
  // rules and describes exactly the brute-force surface.
  std::optional<std::string> chains(const Landscape& l, const ChangeSet& changes) {
    const ChainUpdate u = tracker_.update(l, changes);
    if (changes.empty() && !u.empty()) return "an empty change set changed the chains";
    for (ChainId id : u.removed)
      if (mirror_.erase(id) != 1) return "the tracker removed unknown chain " + std::to_string(id);
    for (const auto& [id, chain] : u.added)
      if (!mirror_.emplace(id, chain).second)
        return "the tracker added known chain " + std::to_string(id);
    return surface(l);
  }

  std::optional<std::string> surface(const Landscape& l) {
    const std::vector<SurfaceChain> full = surface_chains(l, options_);
    std::vector<SurfaceChain> mirrored;
    for (const auto& [id, chain] : mirror_) mirrored.push_back(chain);
    if (sorted(mirrored) != sorted(full))
      return "the tracker's mirror differs from surface_chains() (" +
             std::to_string(mirrored.size()) + " chains against " + std::to_string(full.size()) +
             ")";
    for (std::size_t i = 0; i < full.size(); ++i)
      if (const std::string why = test::chain_rule_violation(full[i]); !why.empty())
        return "chain " + std::to_string(i) + " breaks a chain rule: " + why;
    const std::string diff =
        test::surface_difference(test::surface_brute(l, options_), test::surface_of(full));
    if (!diff.empty()) return "surface_chains() differs from the brute-force surface: " + diff;
    return std::nullopt;
  }

  // mesh_update names the removed ids and meshes every added polygon exactly.
  static std::optional<std::string> meshes(const ChangeSet& changes) {
    const MeshUpdate u = mesh_update(changes);
    if (u.dropped != changes.removed) return "mesh_update drops other ids than the change set";
    if (u.built.size() != changes.added.size()) return "mesh_update builds a mesh per polygon";
    for (std::size_t k = 0; k < u.built.size(); ++k) {
      const PolygonMesh& m = u.built[k];
      const ChangeSet::Added& a = changes.added[k];
      if (m.id != a.id || m.material != a.material || m.vertices != a.polygon)
        return "mesh of polygon " + std::to_string(a.id) + " is not its own";
      std::string why = testing::triangulation_defect(a.polygon, m.triangles);
      if (why.empty()) why = testing::diagonal_defect(a.polygon, m.triangles);
      if (!why.empty()) return "mesh of polygon " + std::to_string(a.id) + ": " + why;
    }
    return std::nullopt;
  }

  // convex_pieces of every added polygon: at most 8 vertices, strictly convex, exactly it.
  static std::optional<std::string> pieces(const ChangeSet& changes) {
    for (const ChangeSet::Added& a : changes.added) {
      const std::vector<Polygon> p = convex_pieces(a.polygon);
      std::string why = testing::convex_pieces_defect(a.polygon, p, kDefaultMaxPieceVertices);
      if (why.empty()) why = testing::union_defect(a.polygon, p);
      if (!why.empty()) return "convex pieces of polygon " + std::to_string(a.id) + ": " + why;
    }
    return std::nullopt;
  }

  // The tracker's islands equal the brute-force components; the update reports exactly the
  // new ones, each with its pieces' exact area.
  std::optional<std::string> islands(const Landscape& l, const ChangeSet& changes,
                                     std::vector<Island>& fresh) {
    fresh = islands_.update(l, changes);
    const std::set<IdSet> now = test::islands_brute(l, options_.materials);
    std::set<IdSet> expected_new, reported;
    for (const IdSet& s : now)
      if (!known_.count(s)) expected_new.insert(s);
    for (const Island& island : fresh) {
      reported.insert(test::ids_of(island));
      Int128 area = 0;
      for (const IslandPiece& p : island.pieces) area += twice_signed_area(p.polygon);
      if (area != island.twice_area) return "an island's area is not its pieces' sum";
    }
    known_ = now;
    if (reported != expected_new)
      return "the update reported " + std::to_string(reported.size()) + " new islands, " +
             std::to_string(expected_new.size()) + " expected";
    std::set<IdSet> tracked;
    for (const Island& island : islands_.islands(l)) tracked.insert(test::ids_of(island));
    if (tracked != now || islands_.island_count() != now.size())
      return "the tracker's islands differ from the brute-force components";
    return std::nullopt;
  }

  SurfaceOptions options_;
  SurfaceTracker tracker_;
  Mirror mirror_;
  IslandTracker islands_;
  std::set<IdSet> known_;  // the brute-force islands after the last change set
};

// An island detached from a copy: the copy passes check(), the island's polygons are gone and
// the regions hold exactly its area. Over a limit (an island's region bigger than the shape
// limit), the copy must be unchanged.
std::optional<std::string> detach_copy(const Landscape& l, const Island& island) {
  Landscape copy = l;
  const std::uint64_t before = copy.state_hash();
  DetachedIsland d;
  try {
    d = detach(copy, island);
  } catch (const LimitExceeded&) {
    if (copy.state_hash() != before) return "a detach over a limit changed the landscape";
    return std::nullopt;
  }
  if (const LandscapeReport r = copy.check(); !r.ok())
    return "check() after a detach: " + r.problems.front();
  Int128 area = 0;
  for (const DetachedIsland::Region& region : d.regions)
    for (const Polygon& p : region.polygons) area += twice_signed_area(p);
  if (area != island.twice_area || d.twice_area != island.twice_area)
    return "a detached island's regions do not hold its area";
  std::set<PolygonId> ids;
  for (const IslandPiece& p : island.pieces) ids.insert(p.id);
  bool left = false;
  copy.polygons_in(copy.world(), [&](const PolygonView& v) {
    left = left || ids.count(v.id) > 0;
    return !left;
  });
  if (left) return "a detached island's polygon is still in the landscape";
  return std::nullopt;
}

Edit as_edit(const DecodedEdit& d) {
  ValidSet shape(d.shape, Operand::kClip);
  switch (d.kind) {
    case 0:
      return Edit::carve(std::move(shape));
    case 1:
      return Edit::fill(std::move(shape), d.a);
    case 2:
      return Edit::fill_empty(std::move(shape), d.a);
    case 3:
      return Edit::replace(std::move(shape), d.a, d.b);
    default:
      return Edit::relabel(std::move(shape), d.map);
  }
}

// A game driver fed frames of the same edits; after each frame its updates, mirrored, must equal
// full exports and the brute-force surface, the islands left must be those it says wait, and
// its debris must hold exactly the area it took, in valid convex pieces.
class DriverCheck {
 public:
  DriverCheck(const Landscape& l, const SurfaceOptions& options, std::size_t budget)
      : game_(l, game_options(options, budget)), chains_(game_.chains()) {
    for (PolygonMesh& m : all_meshes(l)) meshes_.emplace(m.id, std::move(m));
  }

  void add(const DecodedEdit& d) { frame_.push_back(as_edit(d)); }

  std::optional<std::string> end_frame() {
    GameUpdate u;
    const std::uint64_t before = game_.landscape().state_hash();
    const std::size_t chains_before = game_.chains().size();
    try {
      u = game_.apply(frame_);
    } catch (const LimitExceeded&) {  // its landscape differs from the trackers': may be fuller
      frame_.clear();
      if (game_.landscape().state_hash() != before || game_.chains().size() != chains_before)
        return "game driver: a refused frame changed the driver";
      return std::nullopt;
    }
    frame_.clear();
    if (auto e = mirror(u)) return "game driver: " + *e;
    if (auto e = check_state()) return "game driver: " + *e;
    for (const Debris& d : u.debris)
      if (auto e = check_debris(d)) return "game driver debris: " + *e;
    return std::nullopt;
  }

 private:
  static GameOptions game_options(const SurfaceOptions& surface, std::size_t budget) {
    GameOptions o;
    o.surface = surface;
    o.debris_budget = budget;
    return o;
  }

  std::optional<std::string> mirror(const GameUpdate& u) {
    for (ChainId id : u.chains.removed)
      if (chains_.erase(id) != 1) return "removed unknown chain " + std::to_string(id);
    for (const auto& [id, chain] : u.chains.added)
      if (!chains_.emplace(id, chain).second) return "added known chain " + std::to_string(id);
    for (PolygonId id : u.meshes.dropped)
      if (meshes_.erase(id) != 1) return "dropped unknown mesh " + std::to_string(id);
    for (const PolygonMesh& m : u.meshes.built)
      if (!meshes_.emplace(m.id, m).second) return "built known mesh " + std::to_string(m.id);
    return std::nullopt;
  }

  std::optional<std::string> check_state() const {
    const Landscape& l = game_.landscape();
    if (const LandscapeReport r = l.check(); !r.ok()) return "check(): " + r.problems.front();
    std::vector<SurfaceChain> mirrored;
    for (const auto& [id, chain] : chains_) mirrored.push_back(chain);
    const SurfaceOptions& options = game_.options().surface;
    if (sorted(mirrored) != sorted(surface_chains(l, options)))
      return "the chain mirror differs from surface_chains()";
    const std::string diff =
        test::surface_difference(test::surface_brute(l, options), test::surface_of(mirrored));
    if (!diff.empty()) return "the chain mirror differs from the brute-force surface: " + diff;
    std::vector<PolygonMesh> meshes;
    for (const auto& [id, m] : meshes_) meshes.push_back(m);
    if (meshes != all_meshes(l)) return "the mesh mirror differs from all_meshes()";
    if (test::islands_brute(l, options.materials).size() != game_.debris_waiting())
      return "the islands left are not those waiting";
    return std::nullopt;
  }

  std::optional<std::string> check_debris(const Debris& d) const {
    Int128 regions = 0;
    for (const Debris::Region& r : d.regions)
      for (const Polygon& p : r.polygons) regions += twice_signed_area(p);
    if (regions != d.twice_area) return "regions do not hold the island's area";
    Int128 pieces = 0;
    for (const DebrisPiece& p : d.pieces) {
      if (p.polygon.size() > game_.options().max_piece_vertices) return "a piece too big";
      if (!validate(PolygonSet{p.polygon}, 1).ok()) return "an invalid piece";
      pieces += twice_signed_area(p.polygon);
    }
    if (pieces != d.twice_area) return "pieces do not hold the island's area";
    return std::nullopt;
  }

  GameDriver game_;
  Mirror chains_;
  std::map<PolygonId, PolygonMesh> meshes_;
  std::vector<Edit> frame_;
};

Finding finding(const std::string& what, const SurfaceOptions& o, const Landscape& l) {
  return {what + "\n  materials: " + options_text(o) + "\n  landscape state hash " +
              std::to_string(l.state_hash()),
          l.log()};
}

// The edit's change set through every check; each new island is detached from a copy, and,
// when `for_real`, from the landscape itself (the loop of islands.hpp: a stale one is skipped
// and reported again re-cut), each detach's change set checked in turn.
std::optional<std::string> check_edit(Landscape& l, GameCheck& game, const ChangeSet& changes,
                                      bool for_real) {
  std::vector<Island> pending;
  if (auto e = game.after(l, changes, pending)) return e;
  for (const Island& island : pending)
    if (auto e = detach_copy(l, island)) return e;
  while (for_real && !pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    DetachedIsland d;
    try {
      d = detach(l, island);
    } catch (const StaleIsland&) {
      continue;
    } catch (const LimitExceeded&) {
      continue;  // detach_copy checked that nothing changed
    }
    if (const LandscapeReport r = l.check(); !r.ok())
      return "check() after a detach: " + r.problems.front();
    std::vector<Island> again;
    if (auto e = game.after(l, d.changes, again)) return "after a detach: " + *e;
    for (Island& i : again) pending.push_back(std::move(i));
  }
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_game_sequence(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  EditDecoder decode(in);
  Landscape l = decode_world(in, decode);
  const SurfaceOptions options = decode_options(in);
  l.set_checked(true);
  l.start_log();
  const std::size_t budget = in.ConsumeIntegralInRange<std::size_t>(0, 256);
  try {
    GameCheck game(l, options);
    DriverCheck driver(l, options, budget);
    if (auto e = game.start(l)) return finding(*e, options, l);
    for (int i = 0; i < kMaxEdits && in.remaining_bytes() > 0; ++i) {
      const DecodedEdit d = next_edit(in, decode, l);
      if (!d.builder_problem.empty())
        return finding("shape builder: " + d.builder_problem, options, l);
      const bool for_real = in.ConsumeBool();
      ChangeSet changes;
      try {
        changes = apply(l, d);
      } catch (const LandscapeInternalError& e) {
        return Finding{std::string(e.what()) + "\n  edit: " + edit_text(d), e.log};
      } catch (const InvalidInput&) {
        continue;  // edit_sequence checks that nothing changed
      } catch (const LimitExceeded&) {
        continue;
      }
      if (auto e = check_edit(l, game, changes, for_real))
        return finding(*e + "\n  edit: " + edit_text(d), options, l);
      driver.add(d);
      if (in.ConsumeBool())
        if (auto e = driver.end_frame())
          return finding(*e + "\n  frame ends at: " + edit_text(d), options, l);
    }
    if (auto e = driver.end_frame()) return finding(*e + " (the last frame)", options, l);
  } catch (const std::exception& e) {
    return finding(std::string("the game layer threw ") + e.what(), options, l);
  }
  return std::nullopt;
}

}  // namespace edgeland::fuzz
