// GameDriver (game_driver.hpp): mirrors of the chains and meshes kept only from its updates equal
// full exports after every frame; islands never stay in the landscape longer than the debris
// queue allows, and their debris holds exactly the area carved; one solid-boundary pass per
// changed cell; the strong guarantee on a bad edit; buried bodies; reset() after an undo.
#include "edgeland/game/game_driver.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "edgeland/game/islands.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/game/surface_chains.hpp"
#include "edgeland/kernel/area.hpp"
#include "game_worlds.hpp"
#include "landscape_cases.hpp"

namespace edgeland::test {
namespace {

using ChainMirror = std::map<ChainId, SurfaceChain>;
using MeshMirror = std::map<PolygonId, PolygonMesh>;

template <class Mirror, class Added, class KeyOf>
void apply_lists(Mirror& mirror, const std::vector<std::uint64_t>& removed,
                 const std::vector<Added>& added, KeyOf key_of) {
  for (std::uint64_t id : removed)
    if (mirror.erase(id) != 1u) RC_FAIL("removed an unknown id " + std::to_string(id));
  for (const Added& a : added)
    if (!mirror.emplace(key_of(a), a).second) RC_FAIL("added a known id");
}

void apply_update(ChainMirror& chains, MeshMirror& meshes, const GameUpdate& u) {
  RC_ASSERT(std::is_sorted(u.chains.removed.begin(), u.chains.removed.end()));
  RC_ASSERT(std::is_sorted(u.changes.removed.begin(), u.changes.removed.end()));
  for (ChainId id : u.chains.removed)
    if (chains.erase(id) != 1u) RC_FAIL("removed an unknown chain " + std::to_string(id));
  for (const auto& [id, chain] : u.chains.added)
    if (!chains.emplace(id, chain).second) RC_FAIL("added a known chain " + std::to_string(id));
  apply_lists(meshes, u.meshes.dropped, u.meshes.built, [](const PolygonMesh& m) { return m.id; });
}

bool chain_less(const SurfaceChain& l, const SurfaceChain& r) {
  auto key = [](const SurfaceChain& c) {
    return std::tie(c.cell.min, c.cell.max, c.points, c.materials, c.closed, c.ghost_prev,
                    c.ghost_next);
  };
  return key(l) < key(r);
}

std::vector<SurfaceChain> sorted(std::vector<SurfaceChain> v) {
  std::sort(v.begin(), v.end(), chain_less);
  return v;
}

std::vector<SurfaceChain> values(const ChainMirror& m) {
  std::vector<SurfaceChain> out;
  for (const auto& [id, c] : m) out.push_back(c);
  return out;
}

std::vector<PolygonMesh> values(const MeshMirror& m) {
  std::vector<PolygonMesh> out;
  for (const auto& [id, mesh] : m) out.push_back(mesh);
  return out;
}

GameOptions random_options() {
  GameOptions options;
  options.surface.border_wall = *rc::gen::arbitrary<bool>();
  for (int m = 1; m < 6; ++m) {
    options.surface.materials.solid[m] = *rc::gen::inRange(0, 4) != 0;
    options.surface.materials.anchored[m] = *rc::gen::inRange(0, 4) == 0;
  }
  options.debris_budget = *rc::gen::element<std::size_t>(0, 64, 1u << 20);
  options.max_debris_wait = *rc::gen::inRange<std::size_t>(0, 4);
  return options;
}

// The case's edits cut into frames of 1-3.
std::vector<std::vector<Edit>> frames_of(const std::vector<LandscapeEdit>& edits) {
  std::vector<std::vector<Edit>> out;
  for (std::size_t i = 0; i < edits.size();) {
    const std::size_t n = std::min(edits.size() - i, *rc::gen::inRange<std::size_t>(1, 4));
    out.emplace_back();
    for (std::size_t k = 0; k < n; ++k) out.back().push_back(as_edit(edits[i + k]));
    i += n;
  }
  return out;
}

RC_GTEST_PROP(GameDriverProperty, MirrorsOfUpdatesEqualFullExportsAfterEveryFrame, ()) {
  const LandscapeCase c = *landscape_case(12);
  const GameOptions options = random_options();
  Landscape world(c.world, c.fill, c.config);
  world.set_checked(true);  // the driver's own stage checks run too
  GameDriver game(std::move(world), options);
  ChainMirror chains = game.chains();
  MeshMirror meshes;
  for (PolygonMesh& m : all_meshes(game.landscape())) meshes.emplace(m.id, std::move(m));
  std::size_t waiting = game.debris_waiting();
  for (const std::vector<Edit>& frame : frames_of(c.edits)) {
    const GameUpdate u = game.apply(frame);
    apply_update(chains, meshes, u);
    RC_ASSERT(chains == game.chains());
    RC_ASSERT(sorted(values(chains)) == sorted(surface_chains(game.landscape(), options.surface)));
    RC_ASSERT(values(meshes) == all_meshes(game.landscape()));
    // Islands left in the landscape are exactly those waiting in the queue.
    RC_ASSERT(find_islands(game.landscape(), options.surface.materials).size() ==
              game.debris_waiting());
    RC_ASSERT(u.debris_waiting == game.debris_waiting());
    // Debris comes from islands that waited or that this frame made.
    RC_ASSERT(u.debris.size() <= waiting + u.work.islands_found);
    waiting = game.debris_waiting();
  }
  RC_CLASSIFY(game.landscape().stats().cells > 1, "several cells");
}

// The debris of an update holds exactly the solid area its detach carved, its pieces tile its
// regions, and a large budget leaves no island behind.
RC_GTEST_PROP(GameDriverProperty, DebrisHoldsTheAreaItTookOut, ()) {
  const LandscapeCase c = *landscape_case(12);
  GameOptions options;
  options.debris_budget = std::size_t{1} << 30;
  GameDriver game(Landscape(c.world, c.fill, c.config), options);
  game.apply(std::span<const Edit>{});  // the islands the world starts with
  for (const std::vector<Edit>& frame : frames_of(c.edits)) {
    const GameUpdate u = game.apply(frame);
    RC_ASSERT(game.debris_waiting() == 0u);
    RC_ASSERT(find_islands(game.landscape(), options.surface.materials).empty());
    for (const Debris& d : u.debris) {
      Int128 regions = 0, pieces = 0;
      for (const Debris::Region& r : d.regions)
        for (const Polygon& p : r.polygons) regions += twice_signed_area(p);
      for (const DebrisPiece& p : d.pieces) {
        RC_ASSERT(p.polygon.size() <= options.max_piece_vertices);
        pieces += twice_signed_area(p.polygon);
      }
      RC_ASSERT(regions == d.twice_area);
      RC_ASSERT(pieces == d.twice_area);
    }
  }
}

// However small the budget, no island waits longer than max_debris_wait updates: a big one is
// made in steps over several updates, then carved out; once the edits stop, the queue is empty
// after max_debris_wait + 1 updates, and every island has left the landscape.
RC_GTEST_PROP(GameDriverProperty, NoIslandWaitsLongerThanItsLimit, ()) {
  const LandscapeCase c = *landscape_case(12);
  GameOptions options;
  options.debris_budget = *rc::gen::element<std::size_t>(0, 1, 16);
  options.max_debris_wait = *rc::gen::inRange<std::size_t>(0, 4);
  GameDriver game(Landscape(c.world, c.fill, c.config), options);
  for (const std::vector<Edit>& frame : frames_of(c.edits)) game.apply(frame);
  for (std::size_t i = 0; i <= options.max_debris_wait; ++i) game.apply(std::span<const Edit>{});
  RC_ASSERT(game.debris_waiting() == 0u);
  RC_ASSERT(find_islands(game.landscape(), options.surface.materials).empty());
}

// The case the property above shrank to once (before the fix): a detach re-cut the cells of
// another waiting island, whose job was dropped and queued again from age 0, so with a budget of
// one vertex it was still waiting after max_debris_wait + 1 empty updates.
TEST(GameDriver, AnIslandReCutByANeighboursDetachKeepsItsWait) {
  LandscapeConfig config;
  config.tree = TreeKind::kKdTree;
  config.edge_cap = 32;
  config.merge_below = 10;
  config.min_cell_size = 2;
  GameOptions options;
  options.debris_budget = 1;
  options.max_debris_wait = 2;
  GameDriver game(Landscape({{-300, -300}, {-44, -44}}, kEmpty, config), options);
  const auto fill = [](Polygon p) { return Edit::fill(ValidSet(PolygonSet{std::move(p)}), 1); };
  const auto fill_empty = [](Polygon p) {
    return Edit::fill_empty(ValidSet(PolygonSet{std::move(p)}), 1);
  };
  const std::vector<std::vector<Edit>> frames{
      {fill_empty({{-304, -304}, {-298, -304}, {-298, -298}}),
       fill_empty({{-396, -396}, {-268, -396}, {-268, -268}})},
      {fill({{-226, -206}, {-238, -203}, {-235, -209}, {-235, -210}, {-239, -210},
             {-235, -211}, {-235, -212}, {-239, -214}, {-233, -212}, {-239, -216},
             {-235, -214}, {-239, -219}, {-235, -218}, {-235, -219}, {-234, -219},
             {-233, -218}, {-233, -219}, {-232, -218}, {-232, -219}, {-231, -218},
             {-230, -219}, {-230, -218}, {-229, -219}, {-230, -214}, {-230, -213}})},
      {fill_empty({{-177, -306}, {-171, -306}, {-171, -299}, {-177, -302}}),
       fill_empty({{-396, -396},
                   {-392, -396},
                   {-394, -395},
                   {-395, -395},
                   {-397, -394},
                   {-398, -394},
                   {-396, -395},
                   {-398, -395}})},
      {fill({{-261, -141},
             {-249, -199},
             {-195, -213},
             {-171, -236},
             {-171, -235},
             {-185, -201},
             {-171, -234},
             {-171, -233},
             {-193, -181},
             {-147, -180}})},
      {fill_empty({{-168, -295},
                   {-168, -294},
                   {-169, -294},
                   {-170, -293},
                   {-170, -294},
                   {-172, -293},
                   {-171, -294},
                   {-172, -295},
                   {-172, -296},
                   {-171, -296},
                   {-172, -297},
                   {-172, -298},
                   {-171, -298},
                   {-169, -297},
                   {-168, -298},
                   {-168, -297},
                   {-167, -298},
                   {-166, -298}})}};
  for (const std::vector<Edit>& frame : frames) game.apply(frame);
  for (std::size_t i = 0; i <= options.max_debris_wait; ++i) game.apply(std::span<const Edit>{});
  EXPECT_EQ(game.debris_waiting(), 0u);
  EXPECT_TRUE(find_islands(game.landscape(), options.surface.materials).empty());
}

// The case MirrorsOfUpdatesEqualFullExportsAfterEveryFrame shrank to with the queue's order
// checked (before the fix): an island found again kept its wait but was queued behind younger
// jobs, so the pass, which stops at the first job that stops, could leave it past its limit.
TEST(GameDriver, AnIslandFoundAgainIsQueuedBeforeYoungerJobs) {
  LandscapeConfig config;
  config.tree = TreeKind::kKdTree;
  config.edge_cap = 40;
  config.merge_below = 13;
  config.min_cell_size = 2;
  GameOptions options;
  options.surface.border_wall = false;
  for (int m = 1; m < 6; ++m) {
    options.surface.materials.solid[m] = m == 1;
    options.surface.materials.anchored[m] = m != 1;
  }
  options.debris_budget = 0;
  options.max_debris_wait = 2;
  Landscape world({{-300, -300}, {-236, -236}}, kEmpty, config);
  world.set_checked(true);  // the queue's order is checked before every debris pass
  GameDriver game(std::move(world), options);
  const auto edit = [](Edit::Kind kind, Polygon p) {
    ValidSet shape(PolygonSet{std::move(p)});
    return kind == Edit::Kind::kFill ? Edit::fill(std::move(shape), 1)
                                     : Edit::fill_empty(std::move(shape), 1);
  };
  const std::vector<Edit> edits{
      edit(Edit::Kind::kFillEmpty, {{-329, -329},
                                    {-325, -329},
                                    {-327, -328},
                                    {-328, -328},
                                    {-330, -327},
                                    {-331, -327},
                                    {-329, -328},
                                    {-331, -328}}),
      edit(Edit::Kind::kFillEmpty, {{-250, -275}, {-247, -275}, {-247, -269}}),
      edit(Edit::Kind::kFill, {{-300, -300}, {-298, -299}, {-299, -299}}),
      edit(Edit::Kind::kFill, {{-249, -275}, {-262, -275}, {-262, -285}})};
  for (const Edit& e : edits) EXPECT_NO_THROW(game.apply(std::span<const Edit>(&e, 1)));
  for (std::size_t i = 0; i <= options.max_debris_wait; ++i)
    EXPECT_NO_THROW(game.apply(std::span<const Edit>{}));
  EXPECT_EQ(game.debris_waiting(), 0u);
  EXPECT_TRUE(find_islands(game.landscape(), options.surface.materials).empty());
}

// A networked game (net/README.md, "Debris"): the server's driver detaches debris, and a
// client whose driver never does (debris off) reaches the server's state by applying the frame's
// edits and then the carve of every debris polygon of the update, the COMMAND the server sends.
RC_GTEST_PROP(GameDriverProperty, ADetachmentIsTheCarveOfItsDebrisOnAClientWithoutDebris, ()) {
  const LandscapeCase c = *landscape_case(12);
  const GameOptions options = random_options();
  GameOptions client_options = options;
  client_options.debris = false;
  GameDriver server(Landscape(c.world, c.fill, c.config), options);
  GameDriver client(Landscape(c.world, c.fill, c.config), client_options);
  const auto follow = [&](const GameUpdate& u) {
    PolygonSet carved;
    for (const Debris& d : u.debris)
      for (const Debris::Region& r : d.regions)
        carved.insert(carved.end(), r.polygons.begin(), r.polygons.end());
    if (!carved.empty()) client.apply(Edit::carve(ValidSet(std::move(carved))));
    RC_ASSERT(client.landscape().state_hash() == server.landscape().state_hash());
  };
  bool debris = false;
  const GameUpdate first = server.apply(std::span<const Edit>{});  // the islands it starts with
  follow(first);
  debris = !first.debris.empty();
  for (const std::vector<Edit>& frame : frames_of(c.edits)) {
    const GameUpdate u = server.apply(frame);
    client.apply(frame);
    follow(u);
    debris = debris || !u.debris.empty();
  }
  RC_CLASSIFY(debris, "debris detached");
}

// Each cell an update replaced is read and cut once (stage 1), whatever it feeds.
RC_GTEST_PROP(GameDriverProperty, OneBoundaryPassPerChangedCell, ()) {
  const LandscapeCase c = *landscape_case(10);
  GameOptions options;
  options.debris = false;
  GameDriver game(Landscape(c.world, c.fill, c.config), options);
  for (const std::vector<Edit>& frame : frames_of(c.edits)) {
    const GameUpdate u = game.apply(frame);
    RC_ASSERT(u.work.boundary_passes == u.work.cells_scanned);
    RC_ASSERT(u.work.cells_scanned == u.changes.cells.size());
  }
}

// The second edit of a frame passes the shape limit: the first is undone with it.
TEST(GameDriver, ABadEditChangesNothing) {
  LandscapeLimits limits;
  limits.max_shape_vertices = 8;
  Landscape start({{0, 0}, {1024, 1024}}, 1, {}, limits);
  GameDriver game(std::move(start));
  game.apply(Edit::carve(ValidSet(PolygonSet{{{100, 100}, {300, 100}, {300, 700}, {100, 700}}})));
  const std::uint64_t hash = game.landscape().state_hash();
  const std::map<ChainId, SurfaceChain> chains = game.chains();
  Polygon many;
  for (std::int64_t i = 0; i < 12; ++i) many.push_back({500 + i, 500 + i * i});
  many.push_back({400, 600});
  const std::vector<Edit> frame{
      Edit::carve(ValidSet(PolygonSet{{{400, 400}, {500, 400}, {450, 500}}})),
      Edit::fill(ValidSet(PolygonSet{many}), 2)};
  EXPECT_THROW(game.apply(frame), LimitExceeded);
  EXPECT_EQ(game.landscape().state_hash(), hash);
  EXPECT_EQ(game.chains(), chains);
}

// Options an update could not honour are refused when the driver is made, not in the middle of
// an update whose edits were already kept.
TEST(GameDriver, PiecesOfFewerThanThreeVerticesAreRefusedUpFront) {
  GameOptions options;
  options.max_piece_vertices = 2;
  try {
    GameDriver game(layered_world(256), options);
    FAIL() << "max_piece_vertices 2 was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.value, 2u);
    EXPECT_EQ(e.minimum, 3u);
  }
  options.max_piece_vertices = 3;
  EXPECT_NO_THROW(GameDriver(layered_world(256), options));
}

TEST(GameDriver, AFillBuriesTheBodiesUnderIt) {
  GameDriver game(layered_world(1024));
  // A pillar of dirt from the ground (dirt ends at y = 640) up through a body in the air.
  const PolygonSet pillar{{{480, 600}, {560, 600}, {560, 860}, {480, 860}}};
  const Box64 in_the_air{{500, 800}, {520, 820}}, far_away{{100, 900}, {120, 920}};
  EXPECT_FALSE(game.buried(in_the_air));
  game.apply(Edit::fill(ValidSet(pillar), 2));
  EXPECT_TRUE(game.buried(in_the_air));
  EXPECT_FALSE(game.buried(far_away));
  game.apply(Edit::carve(ValidSet(pillar)));
  EXPECT_FALSE(game.buried(in_the_air));  // a carve buries nothing
}

TEST(GameDriver, ABlockCutLooseFallsAsOneBodyAtItsCentroid) {
  GameDriver game(layered_world(1024));
  // A moat around a block of rock: the block is an island.
  const PolygonSet moat{{{200, 200}, {400, 200}, {400, 210}, {200, 210}},
                        {{200, 390}, {400, 390}, {400, 400}, {200, 400}},
                        {{200, 210}, {210, 210}, {210, 390}, {200, 390}},
                        {{390, 210}, {400, 210}, {400, 390}, {390, 390}}};
  const GameUpdate u = game.apply(Edit::carve(ValidSet(moat)));
  ASSERT_EQ(u.debris.size(), 1u);
  const Debris& d = u.debris.front();
  EXPECT_EQ(d.twice_area, Int128(2) * 180 * 180);
  EXPECT_EQ(d.centroid.x_num / d.centroid.den, 300);
  EXPECT_EQ(d.centroid.y_num / d.centroid.den, 300);
  ASSERT_EQ(d.regions.size(), 1u);
  EXPECT_EQ(d.regions.front().polygons.size(), 1u);  // one outline, not the cells it lay in
  EXPECT_EQ(game.landscape().material_at({300, 300}), kEmpty);
}

TEST(GameDriver, ResetAfterAnUndoNamesWhatChanged) {
  GameDriver game(layered_world(1024));
  const Landscape before = game.landscape();
  ChainMirror chains = game.chains();
  MeshMirror meshes;
  for (PolygonMesh& m : all_meshes(game.landscape())) meshes.emplace(m.id, std::move(m));
  apply_update(chains, meshes,
               game.apply(Edit::carve(ValidSet(PolygonSet{{{100, 100}, {300, 100}, {200, 700}}}))));
  apply_update(chains, meshes, game.reset(before));
  EXPECT_EQ(sorted(values(chains)), sorted(surface_chains(before)));
  EXPECT_EQ(values(meshes), all_meshes(before));
}

TEST(GameDriver, AStoppedDriverSaysWhatStoppedItUntilReset) {
  // A binding that could not hand an update over says so (update_lost()); the driver refuses
  // updates, naming that, until reset() rebuilds it.
  GameDriver game(layered_world(1024));
  const ValidSet hole(PolygonSet{{{100, 100}, {300, 100}, {200, 700}}});
  game.apply(Edit::carve(hole));
  game.update_lost();
  try {
    game.apply(Edit::carve(hole));
    ADD_FAILURE() << "a stopped driver applied an update";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("update_lost()"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reset()"), std::string::npos) << e.what();
  }
  game.reset(game.landscape());
  EXPECT_NO_THROW(
      game.apply(Edit::carve(ValidSet(PolygonSet{{{500, 100}, {600, 100}, {550, 300}}}))));
}

}  // namespace
}  // namespace edgeland::test
