// `edgeland inspect SAVE`: reads a save file (Landscape::load, which validates it completely)
// and prints one JSON line: the file's size, the world and its configuration, the landscape's
// statistics, its area per material, its state hash and the verdict of Landscape::check().
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/io/landscape_replay.hpp"

namespace edgeland::cli {
namespace {

nlohmann::ordered_json box_json(const Box64& b) { return {b.min.x, b.min.y, b.max.x, b.max.y}; }

nlohmann::ordered_json config_json(const LandscapeConfig& c) {
  nlohmann::ordered_json out;
  out["tree"] = c.tree == TreeKind::kQuadtree ? "quadtree" : "kdtree";
  out["edge_cap"] = c.edge_cap;
  out["merge_below"] = c.merge_below;
  out["min_cell_size"] = c.min_cell_size;
  out["grid_depth"] = c.grid_depth;
  return out;
}

// The world a good save file describes.
nlohmann::ordered_json landscape_json(const Landscape& l) {
  const LandscapeStats stats = l.stats();
  nlohmann::ordered_json out;
  out["world"] = box_json(l.world());
  out["config"] = config_json(l.config());
  out["polygons"] = stats.polygons;
  out["vertices"] = stats.vertices;
  out["cells"] = stats.cells;
  out["depth"] = stats.depth;
  out["memory_bytes"] = stats.bytes;
  nlohmann::ordered_json area = nlohmann::ordered_json::object();
  for (const auto& [m, twice] : log::material_areas(l)) area[to_string(m)] = to_string(twice);
  out["area"] = area;
  out["state_hash"] = log::state_hash_hex(l.state_hash());
  return out;
}

// Prints the JSON line; 0 when check() passes, 3 when it does not (load() validates every
// invariant check() does, so a failure is a bug in edgeland).
int report_landscape(nlohmann::ordered_json out, const Landscape& l) {
  const LandscapeReport report = l.check();
  const nlohmann::ordered_json described = landscape_json(l);
  for (const auto& [key, value] : described.items()) out[key] = value;
  out["check"] = report.ok() ? "ok" : "failed";
  if (!report.ok()) out["problems"] = report.problems;
  std::cout << out.dump() << '\n';
  return report.ok() ? kExitOk : kExitInternal;
}

// Prints the JSON line of a file that is no good save file; exit 1 (read, but breaks a rule).
int report_refusal(nlohmann::ordered_json out, const std::string& error) {
  out["valid"] = false;
  out["error"] = error;
  std::cout << out.dump() << '\n';
  return kExitInvalid;
}

int run_inspect(const std::string& path) {
  std::string bytes;
  try {
    bytes = demo::read_input_text(path);
  } catch (const demo::InputError& error) {
    std::cerr << "edgeland inspect: " << error.what() << '\n';
    return kExitUnreadable;
  }
  nlohmann::ordered_json out;
  out["file"] = path;
  out["bytes"] = bytes.size();
  std::istringstream in(bytes);
  try {
    const Landscape landscape = Landscape::load(in);
    out["valid"] = true;
    return report_landscape(out, landscape);
  } catch (const LoadError& error) {
    return report_refusal(out, error.what());
  } catch (const LimitExceeded& error) {
    return report_refusal(out, std::string("beyond the default limits: ") + error.what());
  }
}

}  // namespace

Command add_inspect_command(CLI::App& parent) {
  auto path = std::make_shared<std::string>();
  CLI::App* app = parent.add_subcommand(
      "inspect",
      "Read a landscape save file, check it, and print its world, statistics, areas and state "
      "hash as one JSON line.");
  app->add_option("SAVE", *path, "a save file (Landscape::save, demo --save); - = standard input")
      ->required();
  app->footer(
      "Exit status: 0 for a good save file (\"check\":\"ok\"); 1 for a file that is read but is "
      "no good save file (damaged, truncated, another format or version, a world that breaks an "
      "invariant, or beyond the default limits: \"valid\":false and \"error\"); 2 for a file "
      "that cannot be read (one line on stderr); 3 when check() fails on a file load() "
      "accepted (a bug in edgeland).");
  return {app, [path] { return run_inspect(*path); }};
}

}  // namespace edgeland::cli
