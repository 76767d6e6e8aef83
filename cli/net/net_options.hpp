#pragma once
// What `edgeland serve`, `client` and `store` share: the world a server starts from, and the store
// it keeps its regions in (store/README.md), with which regions it owns.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "edgeland/net/server.hpp"
#include "edgeland/store/region_store.hpp"

namespace edgeland::cli {

struct WorldArgs {
  std::int64_t size = 8192;  // the world is [0, size]^2
  int region_depth = 3;
  int fill = 1;  // the material the world starts as
};
void add_world_options(CLI::App& app, WorldArgs& a);
// The world the options describe: regions with their own ids.
Landscape make_world(const WorldArgs& a);

struct StoreArgs {
  std::string store;        // "sqlite:PATH" or "postgres:CONNINFO"; empty: no store
  std::string server;       // this server's name among the owners (postgres)
  std::string own = "all";  // the regions this server owns: "all" or indices "0,5,..."
  int commit_ms = 1000;
};
void add_store_options(CLI::App& app, StoreArgs& a);
// Opens the store of "sqlite:PATH" or "postgres:CONNINFO" (a postgres one with `server` as the
// name its commits are checked against). Throws StoreError.
std::unique_ptr<store::RegionStore> open_store(const std::string& spec,
                                               const std::string& server = {});
// Rejections by reason name, as the commands print them.
nlohmann::ordered_json rejects_json(const std::map<net::RejectReason, std::uint64_t>& rejects);

// Region indices from "0,5,12" (InputError-free: throws std::invalid_argument).
std::vector<std::uint32_t> region_list(const std::string& text);

// A server's world and its store: made fresh (no store) or opened from the store (created there
// first when empty), owning the regions asked for, the others unloaded and skipped by edits;
// the owned regions that changed are committed every commit_ms and when the server stops.
class StoreSession {
 public:
  StoreSession(const StoreArgs& a, const WorldArgs& world);
  ~StoreSession();
  Landscape world() const { return world_; }
  // The sequence number the server goes on from (the store's; 0 for a fresh world).
  std::uint64_t sequence() const noexcept { return sequence_; }
  void after_step(const net::Server& server);
  void finish(const net::Server& server);

 private:
  void commit(const net::Server& server);
  StoreArgs args_;
  std::unique_ptr<store::RegionStore> store_;
  Landscape world_;
  std::vector<TreePath> owned_;
  std::vector<std::uint64_t> committed_;  // the hash of each owned region as last committed
  std::uint64_t sequence_ = 0;
  std::chrono::steady_clock::time_point next_commit_;
};

}  // namespace edgeland::cli
