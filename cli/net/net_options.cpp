#include "net_options.hpp"

#include <sstream>
#include <stdexcept>

#include "edgeland/store/postgres_store.hpp"
#include "edgeland/store/sqlite_store.hpp"

namespace edgeland::cli {
namespace {

std::uint32_t index_of(const TreePath& path) {
  std::uint32_t index = 0;
  for (const std::uint8_t d : path) index = index * 4 + d;
  return index;
}

// The world from the store, created there first when the store holds none.
Landscape opened(store::RegionStore& s, const WorldArgs& w) {
  if (!s.world()) store::write_world(s, make_world(w), 0);
  return store::open_world(s);
}

}  // namespace

void add_world_options(CLI::App& app, WorldArgs& a) {
  app.add_option("--world-size", a.size, "the world is [0, size]^2")->default_val(a.size);
  app.add_option("--region-depth", a.region_depth, "the tree's region depth")
      ->default_val(a.region_depth);
  app.add_option("--fill", a.fill, "the material the world starts as (0: empty)")
      ->default_val(a.fill);
}

Landscape make_world(const WorldArgs& a) {
  LandscapeConfig c;
  c.region_depth = a.region_depth;
  c.region_ids = true;
  return Landscape({{0, 0}, {a.size, a.size}}, a.fill, c);
}

void add_store_options(CLI::App& app, StoreArgs& a) {
  app.add_option("--store", a.store, "sqlite:PATH or postgres:CONNINFO (regions kept there)");
  app.add_option("--server-name", a.server, "this server's name among the owners (postgres)");
  app.add_option("--own", a.own, "the regions this server owns: all, or indices 0,5,...")
      ->default_val(a.own);
  app.add_option("--commit-ms", a.commit_ms, "milliseconds between commits of changed regions")
      ->default_val(a.commit_ms);
}

std::unique_ptr<store::RegionStore> open_store(const std::string& spec, const std::string& server) {
  if (spec.rfind("sqlite:", 0) == 0)
    return std::make_unique<store::SqliteRegionStore>(spec.substr(7));
  if (spec.rfind("postgres:", 0) == 0)
    return std::make_unique<store::PostgresRegionStore>(spec.substr(9), server);
  throw store::StoreError("a store is sqlite:PATH or postgres:CONNINFO, not '" + spec + "'");
}

nlohmann::ordered_json rejects_json(const std::map<net::RejectReason, std::uint64_t>& rejects) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [reason, n] : rejects) out[net::reason_name(reason)] = n;
  return out;
}

std::vector<std::uint32_t> region_list(const std::string& text) {
  std::vector<std::uint32_t> out;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    out.push_back(static_cast<std::uint32_t>(std::stoul(item)));
  return out;
}

StoreSession::StoreSession(const StoreArgs& a, const WorldArgs& w)
    : args_(a), world_(make_world(w)) {
  if (a.store.empty()) return;
  {
    // The world is written (when new) without ownership checks: it is nobody's yet.
    const std::unique_ptr<store::RegionStore> plain = open_store(a.store);
    world_ = opened(*plain, w);
  }
  store_ = open_store(a.store, a.server);
  std::vector<TreePath> wanted;
  const std::vector<std::uint32_t> list =
      a.own == "all" ? std::vector<std::uint32_t>{} : region_list(a.own);
  for (const TreePath& p : world_.region_paths())
    if (a.own == "all" || std::find(list.begin(), list.end(), index_of(p)) != list.end())
      wanted.push_back(p);
  auto* pg = dynamic_cast<store::PostgresRegionStore*>(store_.get());
  owned_ = pg && !a.server.empty() ? pg->claim(wanted) : wanted;
  for (const TreePath& p : owned_) {
    store::load_region(*store_, world_, p);
    committed_.push_back(world_.node_digest(p)->hash);
  }
  world_.set_unloaded_policy(UnloadedRegions::kSkip);
  sequence_ = store_->world()->seq;
  next_commit_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(a.commit_ms);
}

StoreSession::~StoreSession() = default;

void StoreSession::after_step(const net::Server& server) {
  if (!store_ || std::chrono::steady_clock::now() < next_commit_) return;
  commit(server);
  next_commit_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(args_.commit_ms);
}

void StoreSession::finish(const net::Server& server) {
  if (store_) commit(server);
}

void StoreSession::commit(const net::Server& server) {
  const Landscape& w = server.world();
  std::vector<store::StoredRegion> rows;
  std::vector<std::pair<std::size_t, std::uint64_t>> written;
  for (std::size_t i = 0; i < owned_.size(); ++i) {
    const std::uint64_t hash = w.node_digest(owned_[i])->hash;
    if (hash == committed_[i]) continue;
    rows.push_back(store::stored_region(w, owned_[i], server.sequence()));
    written.emplace_back(i, hash);
  }
  if (rows.empty()) return;
  store_->commit(rows, store::WorldRecord{w.world(), w.config(), w.next_id(), server.sequence()});
  for (const auto& [i, hash] : written) committed_[i] = hash;
}

}  // namespace edgeland::cli
