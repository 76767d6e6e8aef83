// `edgeland stream`: the streaming run (store/README.md, "StreamingWorld"). The same edits
// (SweepEdits) either in memory or through a region store under a memory budget; prints one JSON
// line: the state hash, the world's size, and the process's baseline and peak resident memory,
// so a script compares the two runs (scripts/streaming_run.sh). With --trace-commits every commit
// is announced before and after it (the crash test kills the writer between the two).
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/store/streaming_world.hpp"
#include "edgeland/store/sweep_edits.hpp"
#include "net_options.hpp"

namespace edgeland::cli {
namespace {

struct StreamArgs {
  std::string store;  // empty: in memory
  std::size_t budget = 64 << 20;
  std::int64_t side = 8192;
  int region_depth = 4;
  std::size_t max_edits = 0;  // 0: all of the sweep
  bool trace = false;
};

// A field of /proc/self/status in kB (VmRSS, VmHWM).
long status_kb(const std::string& field) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  return -1;
}

// A store that says when each commit starts and when it has returned, with what it wrote.
class TracedStore : public store::RegionStore {
 public:
  explicit TracedStore(store::RegionStore& inner) : inner_(inner) {}
  std::optional<store::WorldRecord> world() override { return inner_.world(); }
  std::optional<store::StoredRegion> region(const TreePath& p) override { return inner_.region(p); }
  void for_each_region(const std::function<void(const store::StoredRegion&)>& v) override {
    inner_.for_each_region(v);
  }
  void commit(const std::vector<store::StoredRegion>& rows,
              const std::optional<store::WorldRecord>& w) override {
    std::cout << "commit-begin " << ++commits_ << std::endl;
    inner_.commit(rows, w);
    std::cout << "commit-end " << commits_;
    for (const store::StoredRegion& r : rows) {
      std::cout << ' ' << r.seq << ':';
      for (const std::uint8_t d : r.path) std::cout << static_cast<int>(d);
    }
    std::cout << std::endl;
  }

 private:
  store::RegionStore& inner_;
  std::uint64_t commits_ = 0;
};

nlohmann::ordered_json world_json(const Landscape& w) {
  const LandscapeStats s = w.stats();
  nlohmann::ordered_json out;
  out["vertices"] = s.vertices;
  out["polygons"] = s.polygons;
  out["cells"] = s.cells;
  out["state_hash"] = log::state_hash_hex(w.state_hash());
  return out;
}

std::size_t edits_of(const StreamArgs& a, const store::SweepEdits& sweep) {
  return a.max_edits ? std::min(a.max_edits, sweep.size()) : sweep.size();
}

nlohmann::ordered_json in_memory(const StreamArgs& a, const store::SweepEdits& sweep) {
  Landscape w(sweep.world(), kEmpty, sweep.config());
  for (std::size_t i = 0; i < edits_of(a, sweep); ++i) apply_edit(w, sweep.at(i));
  nlohmann::ordered_json out = world_json(w);
  out["mode"] = "memory";
  out["edits"] = edits_of(a, sweep);
  out["world_bytes"] = w.stats().bytes;
  return out;
}

nlohmann::ordered_json streaming(const StreamArgs& a, const store::SweepEdits& sweep) {
  const std::unique_ptr<store::RegionStore> backing = open_store(a.store);
  if (!backing->world())
    store::write_world(*backing, Landscape(sweep.world(), kEmpty, sweep.config()), 0);
  TracedStore traced(*backing);
  store::RegionStore& s = a.trace ? static_cast<store::RegionStore&>(traced) : *backing;
  store::StreamingWorld w(s, a.budget);
  const std::uint64_t resumed_at = w.sequence();
  while (w.sequence() < edits_of(a, sweep)) w.apply(sweep.at(w.sequence()));
  w.flush();
  nlohmann::ordered_json out = world_json(w.world());
  const store::StreamingWorld::Stats& st = w.stats();
  out["mode"] = "streaming";
  out["edits"] = w.sequence() - resumed_at;
  out["resumed_at"] = resumed_at;
  out["budget"] = a.budget;
  out["peak_loaded_bytes"] = st.peak_loaded_bytes;
  out["loads"] = st.loads;
  out["evictions"] = st.evictions;
  out["writes"] = st.writes;
  out["commits"] = st.commits;
  return out;
}

int run_stream(const StreamArgs& a) {
  const long baseline = status_kb("VmRSS");
  const auto start = std::chrono::steady_clock::now();
  const store::SweepEdits sweep(a.side, a.region_depth);
  nlohmann::ordered_json out = a.store.empty() ? in_memory(a, sweep) : streaming(a, sweep);
  out["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out["baseline_rss_kb"] = baseline;
  out["peak_rss_kb"] = status_kb("VmHWM");
  std::cout << out.dump() << std::endl;
  return kExitOk;
}

}  // namespace

Command add_stream_command(CLI::App& parent) {
  auto a = std::make_shared<StreamArgs>();
  CLI::App* app = parent.add_subcommand(
      "stream",
      "Build a big world region by region, in memory or through a region store under "
      "a memory budget (store/README.md), and print its hash and memory.");
  app->add_option("--store", a->store, "sqlite:PATH or postgres:CONNINFO (none: in memory)");
  app->add_option("--budget", a->budget, "bytes the loaded regions may take")
      ->default_val(a->budget);
  app->add_option("--world-size", a->side, "the world's side, a multiple of 128 << region depth")
      ->default_val(a->side);
  app->add_option("--region-depth", a->region_depth, "the tree's region depth")
      ->default_val(a->region_depth);
  app->add_option("--max-edits", a->max_edits, "stop after this many edits of the sweep (0: all)")
      ->default_val(0);
  app->add_flag("--trace-commits", a->trace, "print commit-begin / commit-end lines");
  app->footer(
      "A store that already holds the sweep's world goes on from its sequence number "
      "(a run resumed after a crash). Exit status 0; 2 for a store that cannot be used.");
  return {app, [a] { return run_stream(*a); }};
}

}  // namespace edgeland::cli
