// `edgeland export LOG [--solid LIST|all] [--anchor LIST] [--max-piece-vertices N]
//   [--border-wall] [--chains FILE] [--pieces FILE] [--mesh FILE] [--islands FILE]`:
// replays a landscape log and writes what a game takes from its final world (game/README.md):
//   --chains   one surface chain per line: LINESTRING (...)<TAB>POINT (prev ghost)<TAB>POINT
//              (next ghost); a closed chain repeats its first point at the end;
//   --pieces   MATERIAL<TAB>POLYGON (...) per convex piece of every solid polygon;
//   --mesh     MATERIAL<TAB>POLYGON ((a, b, c, a)) per triangle of the game layer's render meshes
//              (all_meshes: every polygon, by ascending id);
//   --islands  one debris island per line, MULTIPOLYGON (...) of its region (maximal polygons);
// and prints one JSON line {chains, chain_vertices, pieces, triangles, islands, seconds}.
// A bad log line exits 2 naming it, as `replay` does; the outputs then describe the world
// before that line.
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/game/surface_chains.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "landscape_replay.hpp"

namespace edgeland::cli {
namespace {

struct ExportOptions {
  std::string path;
  std::string solid = "all", anchor;
  std::size_t max_piece_vertices = kDefaultMaxPieceVertices;
  bool border_wall = false;
  std::string chains, pieces, mesh, islands;
};

struct Counts {
  std::size_t chains = 0, chain_vertices = 0, pieces = 0, triangles = 0, islands = 0;
};

class ExportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "1,2,5" -> those materials; "all" -> every material but 0.
std::vector<Material> material_list(const std::string& text, const char* option) {
  std::vector<Material> out;
  if (text == "all") {
    for (int m = 1; m < 256; ++m) out.push_back(m);
    return out;
  }
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    int value = -1;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || value < 0 || value > 255)
      throw ExportError(std::string(option) + ": '" + item + "' is not a material 0..255");
    out.push_back(value);
  }
  return out;
}

PhysicsMaterials physics_materials(const ExportOptions& o) {
  PhysicsMaterials m;
  m.solid.fill(false);
  for (Material s : material_list(o.solid, "--solid")) m.solid[s.value()] = true;
  for (Material a : material_list(o.anchor, "--anchor")) m.anchored[a.value()] = true;
  return m;
}

std::string point_wkt(Point64 p) { return std::to_string(p.x) + " " + std::to_string(p.y); }

std::string chain_line(const SurfaceChain& c) {
  std::string out = "LINESTRING (";
  for (std::size_t i = 0; i < c.points.size(); ++i) out += (i ? ", " : "") + point_wkt(c.points[i]);
  if (c.closed) out += ", " + point_wkt(c.points.front());
  return out + ")\tPOINT (" + point_wkt(c.ghost_prev) + ")\tPOINT (" + point_wkt(c.ghost_next) +
         ")";
}

// Runs `write` into FILE unless FILE is empty; a file that cannot be written is exit 2.
template <class Write>
void write_file(const std::string& path, Write write) {
  if (path.empty()) return;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  write(out);
  if (!out.flush()) throw ExportError("cannot write '" + path + "'");
}

void export_world(const Landscape& world, const ExportOptions& o, Counts& n) {
  SurfaceOptions surface{physics_materials(o), o.border_wall};
  const std::vector<SurfaceChain> chains = surface_chains(world, surface);
  n.chains = chains.size();
  for (const SurfaceChain& c : chains) n.chain_vertices += c.points.size();
  write_file(o.chains, [&](std::ostream& out) {
    for (const SurfaceChain& c : chains) out << chain_line(c) << '\n';
  });
  std::ostringstream pieces, mesh;
  for (const PolygonMesh& m : all_meshes(world)) {
    for (const Triangle& t : m.triangles) {
      const Polygon triangle{m.vertices[t.a], m.vertices[t.b], m.vertices[t.c]};
      mesh << to_string(m.material) << '\t' << to_wkt(triangle) << '\n';
      ++n.triangles;
    }
  }
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    if (!surface.materials.is_solid(v.material)) return true;
    for (const Polygon& piece : convex_pieces(*v.polygon, o.max_piece_vertices)) {
      pieces << to_string(v.material) << '\t' << to_wkt(piece) << '\n';
      ++n.pieces;
    }
    return true;
  });
  write_file(o.pieces, [&](std::ostream& out) { out << pieces.str(); });
  write_file(o.mesh, [&](std::ostream& out) { out << mesh.str(); });
  const std::vector<Island> islands = find_islands(world, surface.materials);
  n.islands = islands.size();
  write_file(o.islands, [&](std::ostream& out) {
    for (const Island& island : islands) {
      PolygonSet region;
      for (const IslandPiece& p : island.pieces) region.push_back(p.polygon);
      out << to_wkt(merge(ValidSet(std::move(region))).set.polygons()) << '\n';
    }
  });
}

int run_export(const ExportOptions& o) {
  try {
    if (o.max_piece_vertices < 3) throw ExportError("--max-piece-vertices must be at least 3");
    physics_materials(o);  // refuse a bad list before the replay
    const log::LandscapeReplay replayed = log::replay_landscape_log(demo::read_input_text(o.path));
    if (!replayed.landscape) throw ExportError(o.path + ": " + replayed.failure->message);
    const auto start = std::chrono::steady_clock::now();
    Counts n;
    export_world(*replayed.landscape, o, n);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::ordered_json out;
    out["chains"] = n.chains;
    out["chain_vertices"] = n.chain_vertices;
    out["pieces"] = n.pieces;
    out["triangles"] = n.triangles;
    out["islands"] = n.islands;
    out["seconds"] = seconds;
    std::cout << out.dump() << '\n';
    if (replayed.failure) {
      std::cerr << "edgeland export: " << o.path << ": " << replayed.failure->message << '\n';
      return exit_status(*replayed.failure);
    }
    return kExitOk;
  } catch (const demo::InputError& e) {
    std::cerr << "edgeland export: " << e.what() << '\n';
  } catch (const ExportError& e) {
    std::cerr << "edgeland export: " << e.what() << '\n';
  }
  return kExitUnreadable;
}

}  // namespace

Command add_export_command(CLI::App& parent) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* app = parent.add_subcommand(
      "export",
      "Replay a landscape log and write what a game takes from its final world: surface chains "
      "with ghost vertices, convex pieces, triangle meshes and debris islands.");
  app->add_option("LOG", o->path, "landscape log, or - for standard input")->required();
  app->add_option("--solid", o->solid, "solid materials: a list such as 1,2,5, or all (default)");
  app->add_option("--anchor", o->anchor, "anchored materials (never fall): a list such as 3");
  app->add_option("--max-piece-vertices", o->max_piece_vertices,
                  "most vertices of a convex piece (default 8, at least 3)");
  app->add_flag("--border-wall", o->border_wall, "export the world border as a wall");
  app->add_option("--chains", o->chains, "write the surface chains here");
  app->add_option("--pieces", o->pieces, "write the convex pieces of the solid polygons here");
  app->add_option("--mesh", o->mesh, "write the triangles of every polygon here");
  app->add_option("--islands", o->islands, "write the debris islands here");
  app->footer(
      "Prints {chains, chain_vertices, pieces, triangles, islands, seconds} as JSON. Exit status: "
      "0; 2 for a bad command line, an unreadable log or file, or at the first bad log line "
      "(the outputs then describe the world before it, and a one-line message names the line); "
      "3 when an edit hits an internal error.");
  return {app, [o] { return run_export(*o); }};
}

}  // namespace edgeland::cli
