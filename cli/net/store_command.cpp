// `edgeland store SPEC`: the world a region store holds (store/README.md), every region loaded
// and checked, printed as one JSON line with its state hash; with --replay, the same edits a
// client of `--seed` makes in `--replay-box` applied in one process to a fresh world, and whether
// the two hashes agree (the two-server test's comparison).
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/net/edit_stream.hpp"
#include "edgeland/spatial/delta.hpp"
#include "net_options.hpp"

namespace edgeland::cli {
namespace {

struct StoreCommandArgs {
  std::string spec;
  WorldArgs world;
  std::uint64_t seed = 1;
  std::size_t count = 0;  // replayed edits (0: no replay)
  std::vector<std::int64_t> box;
};

Landscape stored_world(const std::string& spec) {
  const std::unique_ptr<store::RegionStore> s = open_store(spec);
  Landscape w = store::open_world(*s);
  for (const TreePath& p : w.region_paths()) store::load_region(*s, w, p);
  return w;
}

// The replayed world, and how many of its edits met more than one region.
Landscape replayed(const StoreCommandArgs& a, std::size_t& across) {
  Landscape w = make_world(a.world);
  net::EditStream edits(a.seed, {{a.box[0], a.box[1]}, {a.box[2], a.box[3]}});
  for (std::size_t i = 0; i < a.count; ++i) {
    const Edit e = edits.next();
    across += w.regions_meeting(*bounding_box(e.shape.polygons())).size() > 1 ? 1 : 0;
    apply_edit(w, e);
  }
  return w;
}

int run_store(const StoreCommandArgs& a) {
  std::optional<Landscape> stored;
  try {
    stored.emplace(stored_world(a.spec));
  } catch (const store::StoreError& e) {
    std::cerr << "edgeland store: " << e.what() << '\n';
    return kExitUnreadable;
  } catch (const LoadError& e) {
    std::cerr << "edgeland store: " << e.what() << '\n';
    return kExitInvalid;
  }
  const Landscape& w = *stored;
  const LandscapeReport report = w.check();
  nlohmann::ordered_json out;
  out["regions"] = w.region_paths().size();
  out["polygons"] = w.stats().polygons;
  out["vertices"] = w.stats().vertices;
  out["check"] = report.ok() ? "ok" : report.problems.front();
  out["state_hash"] = log::state_hash_hex(w.state_hash());
  bool same = true;
  if (a.count > 0) {
    std::size_t across = 0;
    const std::uint64_t single = replayed(a, across).state_hash();
    out["replayed_hash"] = log::state_hash_hex(single);
    out["replayed_edits_across_region_lines"] = across;
    same = single == w.state_hash();
    out["same"] = same;
  }
  std::cout << out.dump() << std::endl;
  return report.ok() && same ? kExitOk : kExitInvalid;
}

}  // namespace

Command add_store_command(CLI::App& parent) {
  auto a = std::make_shared<StoreCommandArgs>();
  CLI::App* app = parent.add_subcommand(
      "store", "Load every region of a region store, check the world and print its hash.");
  app->add_option("SPEC", a->spec, "sqlite:PATH or postgres:CONNINFO")->required();
  add_world_options(*app, a->world);
  app->add_option("--replay-seed", a->seed, "the seed of the client edits to replay")
      ->default_val(1);
  app->add_option("--replay-count", a->count, "how many of its edits to replay (0: none)")
      ->default_val(0);
  app->add_option("--replay-box", a->box, "X0 Y0 X1 Y1: the box the client edited in")->expected(4);
  app->footer(
      "Exit status 0 when the world passes check() (and, with --replay-count, has the "
      "replay's hash), 1 otherwise, 2 when the store cannot be read.");
  return {app, [a] { return run_store(*a); }};
}

}  // namespace edgeland::cli
