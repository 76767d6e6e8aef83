// `edgeland render INPUT (--png FILE | --svg FILE) [--cells] [--chains] [--pieces] [--islands]
// [--no-legend] [--size PIXELS]`: a picture of a landscape, from its edit log (replayed by
// edgeland::io) or its save file (Landscape::load), with a legend of the materials
// (landscape_picture.hpp) and optionally the game layer's surface chains, convex pieces and
// debris islands drawn over it.
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/surface_chains.hpp"
#include "edgeland/io/landscape_log.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "landscape_picture.hpp"

namespace edgeland::cli {
namespace {

struct RenderOptions {
  std::string input;
  std::string png, svg;
  bool cells = false;
  bool chains = false, pieces = false, islands = false;
  bool no_legend = false;
  int size = 0;  // the world's long side in pixels; 0: as `replay --png` (256..2048)
};

// Why there is no landscape to draw: the message and the exit status.
struct Refusal {
  std::string message;
  int status = kExitUnreadable;
};

// The world of a landscape log (io's replay): every edit applied, or the first one that fails.
std::optional<Refusal> replay_log(std::string_view text, std::optional<Landscape>& out) {
  log::LandscapeReplay replay = log::replay_landscape_log(text);
  if (replay.failure) {
    const bool internal = replay.failure->kind == log::ReplayFailure::Kind::kInternal;
    return Refusal{replay.failure->message, internal ? kExitInternal : kExitUnreadable};
  }
  out = std::move(replay.landscape);
  return std::nullopt;
}

// A landscape log (first command `world`) or else a save file.
std::optional<Refusal> read_landscape(const std::string& text, std::optional<Landscape>& out) {
  if (log::is_landscape_log(text)) return replay_log(text, out);
  std::istringstream bytes(text);
  try {
    out.emplace(Landscape::load(bytes));
  } catch (const LoadError& error) {
    return Refusal{std::string("neither a landscape log (first command `world`) nor a save "
                               "file: ") +
                   error.what()};
  }
  return std::nullopt;
}

// The collision surface: per-cell chains (solid on the left), ghosts left out.
PictureLayer chains_layer(const Landscape& landscape) {
  PictureLayer layer{.label = "surface chains", .colour = {255, 64, 160}, .line_width = 2};
  layer.closed = false;
  for (const SurfaceChain& chain : surface_chains(landscape)) {
    std::vector<Point64> path = chain.points;
    if (chain.closed) path.push_back(path.front());
    layer.paths.push_back(std::move(path));
  }
  return layer;
}

PictureLayer pieces_layer(const Landscape& landscape) {
  PictureLayer layer{
      .label = "convex pieces", .colour = {255, 255, 255}, .opacity = 0.45, .line_width = 0.75};
  landscape.polygons_in(landscape.world(), [&](const PolygonView& v) {
    for (Polygon& piece : convex_pieces(*v.polygon)) layer.paths.push_back(std::move(piece));
    return true;
  });
  return layer;
}

PictureLayer islands_layer(const Landscape& landscape) {
  PictureLayer layer{
      .label = "debris islands", .colour = {40, 255, 120}, .line_width = 2.5, .fill = true};
  for (const Island& island : find_islands(landscape)) {
    for (const IslandPiece& piece : island.pieces) layer.paths.push_back(piece.polygon);
  }
  return layer;
}

PictureOptions picture_options(const RenderOptions& options, const Landscape& landscape) {
  PictureOptions picture{.cells = options.cells, .legend = !options.no_legend};
  if (options.size > 0) picture.min_long_side = picture.max_long_side = options.size;
  if (options.pieces) picture.layers.push_back(pieces_layer(landscape));
  if (options.islands) picture.layers.push_back(islands_layer(landscape));
  if (options.chains) picture.layers.push_back(chains_layer(landscape));
  return picture;
}

int run_render(const RenderOptions& options) {
  if (options.png.empty() == options.svg.empty()) {
    std::cerr << "edgeland render: give exactly one of --png FILE and --svg FILE\n";
    return kExitUnreadable;
  }
  std::optional<Landscape> landscape;
  try {
    if (const std::optional<Refusal> refusal =
            read_landscape(demo::read_input_text(options.input), landscape)) {
      std::cerr << "edgeland render: " << options.input << ": " << refusal->message << '\n';
      return refusal->status;
    }
    const PictureOptions picture = picture_options(options, *landscape);
    if (options.png.empty()) {
      write_landscape_svg(*landscape, options.svg, picture);
    } else {
      write_landscape_png(*landscape, options.png, picture);
    }
  } catch (const demo::InputError& error) {
    std::cerr << "edgeland render: " << error.what() << '\n';
    return kExitUnreadable;
  } catch (const PictureError& error) {
    std::cerr << "edgeland render: " << error.what() << '\n';
    return kExitUnreadable;
  }
  const LandscapeStats stats = landscape->stats();
  std::cout << (options.png.empty() ? options.svg : options.png) << ": " << stats.polygons
            << " polygons, " << stats.cells << " cells\n";
  return kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& parent) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* app = parent.add_subcommand(
      "render",
      "Draw a landscape, from its edit log or its save file, as PNG or SVG with a legend of "
      "its materials.");
  app->add_option("INPUT", options->input,
                  "a landscape log (first command `world`) or a save file; - = standard input")
      ->required();
  app->add_option("--png", options->png, "Write the picture as PNG to this file");
  app->add_option("--svg", options->svg, "Write the picture as SVG to this file");
  app->add_flag("--cells", options->cells, "Draw the cell lines");
  app->add_flag("--chains", options->chains,
                "Draw the collision surface: the game layer's per-cell surface chains");
  app->add_flag("--pieces", options->pieces, "Draw every polygon's convex pieces (8 vertices)");
  app->add_flag("--islands", options->islands, "Fill the debris islands (solid held by nothing)");
  app->add_flag("--no-legend", options->no_legend, "Leave out the legend's column");
  app->add_option("--size", options->size, "The world's long side in pixels (default 256..2048)")
      ->check(CLI::Range(16, 16384));
  app->footer(
      "North is up. Exit status: 0; 2 for an unreadable input (a bad log line, a shape the "
      "kernel refuses, a damaged save file) or a picture that cannot be written; 3 for an "
      "internal error.");
  return {app, [options] { return run_render(*options); }};
}

}  // namespace edgeland::cli
