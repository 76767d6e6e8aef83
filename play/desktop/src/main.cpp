// `edgeland-play [--script FILE] [--record FILE] [--headless] [--frames N] [--screenshot FILE.png]
// [--log-out FILE] [--seed S] [--save-file FILE] [--frame-dir DIR --frame-every K]`: the desktop
// demo (play/desktop/README.md). Prints one JSON line at the end: what the session did and what its
// checks found.
#include <SDL.h>

#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "picture.hpp"

namespace edgeland::play {
namespace {

struct MainOptions {
  AppOptions app;
  std::string script, record, screenshot, log_out;
  std::string frame_dir;  // every frame_every-th frame as DIR/frame_NNNNN.png
  std::uint64_t frame_every = 4;
  bool headless = false;
  std::uint64_t frames = 0;  // 0: until the window closes
};

// An SDL event as the demo's input, or nothing for events it does not use.
std::optional<InputEvent> from_sdl(const SDL_Event& e, std::uint64_t frame) {
  InputEvent out{.frame = frame};
  const auto key = [&](const char* name) {
    out.kind = InputKind::kKey;
    out.name = name;
    return out;
  };
  const auto tool = [&](const char* name) {
    out.kind = InputKind::kTool;
    out.name = name;
    return out;
  };
  switch (e.type) {
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      if (e.button.button != SDL_BUTTON_LEFT) return std::nullopt;
      out.kind = e.type == SDL_MOUSEBUTTONDOWN ? InputKind::kDown : InputKind::kUp;
      out.x = e.button.x, out.y = e.button.y;
      return out;
    case SDL_MOUSEMOTION:
      out.kind = InputKind::kMove;
      out.x = e.motion.x, out.y = e.motion.y;
      return out;
    case SDL_MOUSEWHEEL:
      out.kind = InputKind::kWheel;
      out.x = e.wheel.y;
      return out;
    case SDL_KEYDOWN: {
      const bool ctrl = (e.key.keysym.mod & KMOD_CTRL) != 0;
      switch (e.key.keysym.sym) {
        case SDLK_z:
          return ctrl ? std::optional(key("ctrl+z")) : std::nullopt;
        case SDLK_y:
          return ctrl ? std::optional(key("ctrl+y")) : std::nullopt;
        case SDLK_F5:
          return key("f5");
        case SDLK_F9:
          return key("f9");
        case SDLK_c:
          return key("c");
        case SDLK_d:
          return key("d");
        case SDLK_b:
          return key("b");
        case SDLK_x:
          return key("x");
        case SDLK_1:
          return tool("explosion");
        case SDLK_2:
          return tool("digger");
        case SDLK_3:
          return tool("fill");
        case SDLK_4:
          return tool("water");
        case SDLK_5:
          return tool("replace");
        case SDLK_6:
          return tool("ball");
        case SDLK_7:
          return tool("box");
        default:
          return std::nullopt;
      }
    }
    default:
      return std::nullopt;
  }
}

nlohmann::ordered_json summary(const App& app) {
  const AppReport& r = app.report();
  const LandscapeStats s = app.world().stats();
  const double frames = static_cast<double>(std::max<std::uint64_t>(1, r.frames));
  const double edits = static_cast<double>(std::max<std::uint64_t>(1, r.edits));
  nlohmann::ordered_json out;
  out["frames"] = r.frames;
  out["edits"] = r.edits;
  out["refused"] = r.refused;
  out["undos"] = r.undos;
  out["redos"] = r.redos;
  out["bodies_dropped"] = r.bodies_dropped;
  out["bodies_buried"] = r.bodies_buried;
  out["bodies"] = app.physics().bodies().size();
  out["inside_solid"] = r.inside_solid;
  out["islands_detached"] = r.islands_detached;
  out["islands_left"] = r.islands_left;
  out["saves"] = r.saves;
  out["loads"] = r.loads;
  out["loads_matching_save"] = r.loads_matching_save;
  out["polygons"] = s.polygons;
  out["cells"] = s.cells;
  out["triangles"] = app.mesh().triangles();
  out["state_hash"] = log::state_hash_hex(app.world().state_hash());
  out["frame_ms_mean"] = r.frame_ms_total / frames;
  out["frame_ms_max"] = r.frame_ms_max;
  out["edit_ms_mean"] = r.edit_ms_total / edits;
  out["collider_ms_mean"] = r.collider_ms_total / edits;
  return out;
}

struct Sdl {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  ~Sdl() {
    if (renderer != nullptr) SDL_DestroyRenderer(renderer);
    if (window != nullptr) SDL_DestroyWindow(window);
    SDL_Quit();
  }
};

// Headless: SDL's dummy video driver and its software renderer (TOOLCHAIN.md pitfall 18; the
// offscreen driver also works, but loads and unloads EGL libraries that leave allocations a leak
// checker reports).
bool open_window(Sdl& sdl, const MainOptions& options) {
  if (options.headless) setenv("SDL_VIDEODRIVER", "dummy", 0);
  if (SDL_Init(SDL_INIT_VIDEO) != 0) return false;
  sdl.window = SDL_CreateWindow("edgeland play", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                options.app.width, options.app.height,
                                options.headless ? SDL_WINDOW_HIDDEN : 0);
  if (sdl.window == nullptr) return false;
  const Uint32 flags = options.headless ? SDL_RENDERER_SOFTWARE
                                        : SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC;
  sdl.renderer = SDL_CreateRenderer(sdl.window, -1, flags);
  if (sdl.renderer == nullptr)
    sdl.renderer = SDL_CreateRenderer(sdl.window, -1, SDL_RENDERER_SOFTWARE);
  return sdl.renderer != nullptr;
}

// The frames: input (SDL and the script), a physics step, drawing. False when the window closed.
class Loop {
 public:
  Loop(App& app, const MainOptions& options, std::vector<InputEvent> script, std::ostream* record)
      : app_(app), options_(options), script_(std::move(script)), record_(record) {}

  bool frame(std::uint64_t n, SDL_Renderer* renderer) {
    const auto start = std::chrono::steady_clock::now();
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      if (e.type == SDL_QUIT) return false;
      if (options_.headless) continue;
      if (const std::optional<InputEvent> input = from_sdl(e, n)) handle(*input);
    }
    while (next_ < script_.size() && script_[next_].frame <= n) handle(script_[next_++]);
    app_.step();
    app_.draw();
    const bool last = options_.frames != 0 && n + 1 == options_.frames;
    if (last && !options_.screenshot.empty()) save_screenshot(renderer, options_.screenshot);
    if (!options_.frame_dir.empty() && n % options_.frame_every == 0) {
      std::array<char, 32> name{};
      std::snprintf(name.data(), name.size(), "/frame_%05llu.png",
                    static_cast<unsigned long long>(n / options_.frame_every));
      save_screenshot(renderer, options_.frame_dir + name.data());
    }
    SDL_RenderPresent(renderer);
    app_.end_frame(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    return true;
  }

 private:
  void handle(const InputEvent& event) {
    if (record_ != nullptr) *record_ << input_line(event);
    app_.handle(event);
  }

  App& app_;
  const MainOptions& options_;
  std::vector<InputEvent> script_;
  std::ostream* record_;
  std::size_t next_ = 0;
};

int run(const MainOptions& options) {
  std::vector<InputEvent> script;
  if (!options.script.empty()) {
    try {
      script = parse_input_script(demo::read_input_text(options.script));
    } catch (const std::exception& error) {
      std::cerr << "edgeland-play: " << options.script << ": " << error.what() << '\n';
      return 2;
    }
  }
  std::ofstream record;
  if (!options.record.empty()) record.open(options.record, std::ios::trunc);
  Sdl sdl;
  if (!open_window(sdl, options)) {
    std::cerr << "edgeland-play: no window: " << SDL_GetError() << '\n';
    return 2;
  }
  App app(sdl.renderer, options.app);
  Loop loop(app, options, std::move(script), record.is_open() ? &record : nullptr);
  try {
    for (std::uint64_t n = 0; options.frames == 0 || n < options.frames; ++n) {
      if (!loop.frame(n, sdl.renderer)) break;
    }
  } catch (const PictureFailure& error) {
    std::cerr << "edgeland-play: " << error.what() << '\n';
    return 2;
  }
  std::cout << summary(app).dump() << '\n';
  release_text_caches();
  if (!options.log_out.empty()) {
    std::ofstream log(options.log_out, std::ios::binary | std::ios::trunc);
    log << app.world().log();
    if (!log.flush()) return 2;
  }
  return 0;
}

}  // namespace
}  // namespace edgeland::play

int main(int argc, char** argv) {
  edgeland::play::MainOptions options;
  CLI::App cli(
      "edgeland-play: the desktop demo: a landscape to carve, fill and flood under the "
      "mouse, with balls and boxes rolling on it (Box2D).");
  cli.add_option("--script", options.script, "Replay recorded input (mouse and keys per frame)");
  cli.add_option("--record", options.record, "Record the input of this session into a script");
  cli.add_flag("--headless", options.headless,
               "No display: SDL's dummy video driver and software renderer");
  cli.add_option("--frames", options.frames, "Stop after N frames (0: when the window closes)");
  cli.add_option("--screenshot", options.screenshot, "Save the last frame as PNG (needs --frames)");
  cli.add_option("--frame-dir", options.frame_dir,
                 "Save frames as DIR/frame_NNNNN.png (an animation's pictures)");
  cli.add_option("--frame-every", options.frame_every, "Every K-th frame for --frame-dir")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cli.add_option("--log-out", options.log_out, "Write the world's edit log here at the end");
  cli.add_option("--seed", options.app.seed, "The demo world's seed")->capture_default_str();
  cli.add_option("--save-file", options.app.save_file, "Where F5 saves and F9 loads")
      ->capture_default_str();
  CLI11_PARSE(cli, argc, argv);
  return edgeland::play::run(options);
}
