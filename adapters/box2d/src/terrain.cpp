// The Box2D 2.4 terrain (terrain.hpp): chains become b2ChainShape fixtures, one per run of one
// material, with the run's neighbours (or the chain's ghosts) as ghost vertices.
#include "edgeland/box2d/terrain.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace edgeland::box2d {
namespace {

// A part of a chain in one material: `segments` segments from point `first` on (modulo the
// chain's size when it is closed).
struct Run {
  std::size_t first = 0, segments = 0;
  Material material = kEmpty;
};

// The chain cut where its material changes. A closed chain's runs start where a material
// begins; a closed chain of one material is one run of all its segments (a loop).
std::vector<Run> runs_of(const SurfaceChain& c) {
  const std::size_t count = c.materials.size();
  std::size_t start = 0;
  if (c.closed)
    while (start < count && c.materials[start] == c.materials[(start + count - 1) % count]) ++start;
  if (start == count) return {{0, count, c.materials[0]}};
  std::vector<Run> out;
  for (std::size_t k = 0; k < count;) {
    const std::size_t s = (start + k) % count;
    std::size_t length = 1;
    while (k + length < count && c.materials[(s + length) % count] == c.materials[s]) ++length;
    out.push_back({s, length, c.materials[s]});
    k += length;
  }
  return out;
}

}  // namespace

namespace {

// The origin's rule (terrain.hpp, UNITS) and the float range, checked on the world's corners.
EngineUnits engine_units(const TerrainOptions& options, const Box64& world) {
  const EngineUnits units{options.origin.value_or(world.min), options.units_per_metre};
  for (const Point64 corner :
       {world.min, world.max, Point64{world.min.x, world.max.y}, Point64{world.max.x, world.min.y}})
    require_in_engine_range(corner, units.origin);
  return units;
}

}  // namespace

OutOfEngineRange::OutOfEngineRange(Point64 p, Point64 o)
    : Error("point (" + std::to_string(p.x) + " " + std::to_string(p.y) + ") lies more than 2^24 " +
            "units from the engine origin (" + std::to_string(o.x) + " " + std::to_string(o.y) +
            "): Box2D's floats cannot hold it exactly"),
      point(p),
      origin(o) {}

void require_in_engine_range(Point64 p, Point64 origin) {
  const auto far = [](std::int64_t a, std::int64_t b) {
    return static_cast<Int128>(a) - b > kMaxEngineOffset ||
           static_cast<Int128>(b) - a > kMaxEngineOffset;
  };
  if (far(p.x, origin.x) || far(p.y, origin.y)) throw OutOfEngineRange(p, origin);
}

b2Vec2 to_b2(const EngineUnits& units, Point64 p) {
  const EngineVec v = units.to_engine(p);
  return {static_cast<float>(v.x), static_cast<float>(v.y)};
}

Terrain::Terrain(b2World& world, const GameDriver& game, const TerrainOptions& options)
    : world_(world),
      units_(engine_units(options, game.landscape().world())),
      friction_(options.friction),
      world_box_(game.landscape().world()),
      grid_(std::max<std::int64_t>(1, options.body_grid)),
      bodies_(static_cast<std::size_t>(grid_ * grid_), nullptr) {
  for (const auto& [id, chain] : game.chains()) add(id, chain);
  reserve_proxies(options.reserve_proxies.value_or(
      std::max(kDefaultReservedProxies, 2 * static_cast<std::size_t>(world_.GetProxyCount()))));
}

// BROAD PHASE (terrain.hpp): a zig-zag chain of `count` edges a unit of Box2D's space apart,
// beyond the world's lower-left corner (nothing there to pair with), stepped over and destroyed.
void Terrain::reserve_proxies(std::size_t count) {
  if (count <= static_cast<std::size_t>(world_.GetProxyCount())) return;
  const b2Vec2 corner = to_b2(units_, world_box_.min);
  b2BodyDef def;
  def.type = b2_staticBody;
  def.position.Set(corner.x - 1000.0f, corner.y - 1000.0f);
  b2Body* scratch = world_.CreateBody(&def);
  std::vector<b2Vec2>& v = vertices_;
  v.clear();
  for (std::size_t i = 0; i <= count; ++i)
    v.push_back({static_cast<float>(i % 512) * 0.5f,
                 static_cast<float>(i / 512) * 0.5f + static_cast<float>(i % 2) * 0.25f});
  b2ChainShape chain;
  chain.CreateChain(v.data(), static_cast<int32>(v.size()), v.front(), v.back());
  scratch->CreateFixture(&chain, 0.0f);
  world_.Step(0.0f, 0, 0);  // the broad phase forgets the new proxies (else each destroy scans)
  world_.DestroyBody(scratch);
}

Terrain::~Terrain() {
  for (b2Body* body : bodies_)
    if (body != nullptr) world_.DestroyBody(body);
}

std::vector<b2Body*> Terrain::bodies() const {
  std::vector<b2Body*> out;
  for (b2Body* body : bodies_)
    if (body != nullptr) out.push_back(body);
  return out;
}

std::size_t Terrain::fixture_count() const {
  std::size_t n = 0;
  for (const auto& [id, chain] : fixtures_) n += chain.fixtures.size();
  return n;
}

// The region holding the cell's lower-left corner (Int128: the world may span 2^32 units).
std::size_t Terrain::region_of(const Box64& cell) const {
  const auto index = [&](std::int64_t at, std::int64_t lo, std::int64_t hi) {
    const Int128 k = Int128(at - lo) * grid_ / Int128(hi - lo);
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(k), 0, grid_ - 1);
  };
  const std::int64_t x = index(cell.min.x, world_box_.min.x, world_box_.max.x);
  const std::int64_t y = index(cell.min.y, world_box_.min.y, world_box_.max.y);
  return static_cast<std::size_t>(y * grid_ + x);
}

b2Body* Terrain::body_of(std::size_t region) {
  b2Body*& body = bodies_[region];
  if (body == nullptr) {
    b2BodyDef def;
    def.type = b2_staticBody;
    body = world_.CreateBody(&def);
  }
  return body;
}

void Terrain::add(ChainId id, const SurfaceChain& c) {
  const std::size_t region = region_of(c.cell);
  b2Body* body = body_of(region);
  ChainFixtures& record = fixtures_[id];
  record.region = region;
  std::vector<b2Fixture*>& list = record.fixtures;
  const std::size_t n = c.points.size();
  std::vector<b2Vec2>& v = vertices_;
  for (const Run& run : runs_of(c)) {
    b2ChainShape shape;
    v.clear();
    if (c.closed && run.segments == n) {
      for (const Point64& p : c.points) v.push_back(to_b2(units_, p));
      shape.CreateLoop(v.data(), static_cast<int32>(v.size()));
    } else {
      for (std::size_t k = 0; k <= run.segments; ++k)
        v.push_back(to_b2(units_, c.points[(run.first + k) % n]));
      const std::size_t last = run.first + run.segments;  // not reduced: n - 1 ends an open chain
      const Point64 prev =
          !c.closed && run.first == 0 ? c.ghost_prev : c.points[(run.first + n - 1) % n];
      const Point64 next = !c.closed && last == n - 1 ? c.ghost_next : c.points[(last + 1) % n];
      shape.CreateChain(v.data(), static_cast<int32>(v.size()), to_b2(units_, prev),
                        to_b2(units_, next));
    }
    b2FixtureDef def;
    def.shape = &shape;
    def.friction = friction_[run.material.value()];
    def.userData.pointer = run.material.value();
    list.push_back(body->CreateFixture(&def));
  }
}

// The chain's fixtures destroyed; its region is noted in `emptied` (its body may be left empty).
void Terrain::remove(ChainId id, std::vector<std::size_t>& emptied) {
  const auto it = fixtures_.find(id);
  if (it == fixtures_.end()) return;
  for (b2Fixture* f : it->second.fixtures) f->GetBody()->DestroyFixture(f);
  emptied.push_back(it->second.region);
  fixtures_.erase(it);
}

// Removals first, then additions (a region keeps its body across the update); bodies left
// without fixtures are destroyed last.
void Terrain::apply(const GameUpdate& update) {
  std::vector<std::size_t> emptied;
  for (ChainId id : update.chains.removed) remove(id, emptied);
  for (const auto& [id, chain] : update.chains.added) add(id, chain);
  for (std::size_t region : emptied) {
    b2Body*& body = bodies_[region];
    if (body == nullptr || body->GetFixtureList() != nullptr) continue;
    world_.DestroyBody(body);
    body = nullptr;
  }
}

// Fixtures made massless, then the density set on each and the mass computed once: b2Body's
// CreateFixture recomputes the mass over all fixtures whenever one has density (1,601 pieces
// cost 26-35 ms that way; issue 35).
b2Body* make_debris_body(b2World& world, const Debris& debris, const EngineUnits& units,
                         const DebrisOptions& options) {
  require_in_engine_range(debris.bounds.min, units.origin);
  require_in_engine_range(debris.bounds.max, units.origin);
  const EngineVec centre = units.to_engine(debris.centroid);
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(static_cast<float>(centre.x), static_cast<float>(centre.y));
  b2Body* body = world.CreateBody(&def);
  std::vector<b2Vec2> v;
  for (const DebrisPiece& piece : debris.pieces) {
    v.clear();
    for (const Point64& p : piece.polygon) {
      const EngineVec e = units.to_engine(p);
      v.push_back({static_cast<float>(e.x - centre.x), static_cast<float>(e.y - centre.y)});
    }
    b2PolygonShape shape;
    shape.Set(v.data(), static_cast<int32>(v.size()));
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 0;
    fixture.friction = options.friction;
    fixture.restitution = options.restitution;
    fixture.userData.pointer = piece.material.value();
    body->CreateFixture(&fixture);
  }
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) f->SetDensity(options.density);
  body->ResetMassData();
  return body;
}

}  // namespace edgeland::box2d
