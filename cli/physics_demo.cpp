#include "physics_demo.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "landscape_picture.hpp"
#include "physics_scenario.hpp"

namespace edgeland::cli {
namespace {

// A body's fixtures as outlines in world units (circles as 16-gons): pictures only.
void add_outlines(const box2d::PhysicsScene& scene, b2Body* body, PictureLayer& layer) {
  const EngineUnits& units = scene.terrain().units();
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
    std::vector<Point64> path;
    if (f->GetType() == b2Shape::e_circle) {
      const auto* c = static_cast<const b2CircleShape*>(f->GetShape());
      for (int k = 0; k < 16; ++k) {
        const double a = 2 * M_PI * k / 16;
        const b2Vec2 local(c->m_p.x + c->m_radius * static_cast<float>(std::cos(a)),
                           c->m_p.y + c->m_radius * static_cast<float>(std::sin(a)));
        const b2Vec2 p = body->GetWorldPoint(local);
        path.push_back(units.to_world({p.x, p.y}));
      }
    } else if (f->GetType() == b2Shape::e_polygon) {
      const auto* poly = static_cast<const b2PolygonShape*>(f->GetShape());
      for (int i = 0; i < poly->m_count; ++i) {
        const b2Vec2 p = body->GetWorldPoint(poly->m_vertices[i]);
        path.push_back(units.to_world({p.x, p.y}));
      }
    }
    if (path.size() > 2) layer.paths.push_back(std::move(path));
  }
}

PictureOptions frame_picture(const box2d::PhysicsScene& scene) {
  PictureLayer bodies{
      .label = "balls and boxes", .colour = {250, 250, 250}, .line_width = 1.5, .fill = true};
  PictureLayer debris{.label = "debris", .colour = {255, 170, 40}, .line_width = 1.5, .fill = true};
  for (const box2d::SceneBody& b : scene.bodies())
    add_outlines(scene, b.body, b.kind == box2d::BodyKind::kDebris ? debris : bodies);
  PictureOptions options;
  options.max_long_side = 1024;
  options.legend = true;
  options.layers = {std::move(bodies), std::move(debris)};
  return options;
}

std::string frame_path(const std::string& out, int index) {
  std::ostringstream name;
  name << "physics_" << std::setw(4) << std::setfill('0') << index << ".png";
  return (std::filesystem::path(out) / name.str()).string();
}

void print_line(const std::string& label, const std::string& value) {
  std::cout << std::left << std::setw(20) << (label + ":") << value << '\n';
}

std::string per(double seconds, double count, const char* unit) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << (count > 0 ? seconds / count * 1e6 : 0) << " us per "
    << unit;
  return s.str();
}

void print_summary(const box2d::PhysicsScenario& scenario, int frames_written) {
  const box2d::ScenarioStats& a = scenario.stats();
  const box2d::SceneStats& s = scenario.scene().stats();
  print_line("frames", std::to_string(s.steps) + " steps of 1/60 s, " +
                           std::to_string(frames_written) + " pictures");
  print_line("edits", std::to_string(a.edits) + " (blasts and fills near the bodies)");
  print_line("collider updates", std::to_string(s.chains_removed) + " chains removed, " +
                                     std::to_string(s.chains_added) + " added");
  print_line("islands detached", std::to_string(s.detached) + " (falling as debris bodies)");
  print_line("bodies buried", std::to_string(a.buried) + " (a fill put solid on them)");
  print_line("game time", per(a.game_seconds, a.frames, "frame") +
                              " (edits, chains, islands, meshes: GameDriver::apply)");
  print_line("collider time", per(s.collider_seconds, a.frames, "frame"));
  print_line("debris time", per(s.debris_seconds, a.frames, "frame"));
  print_line("step time", per(s.step_seconds, s.steps, "step"));
  print_line("bodies now", std::to_string(scenario.scene().bodies().size()));
  print_line("state hash", log::state_hash_hex(scenario.land().state_hash()));
}

}  // namespace

int run_physics_demo(const PhysicsDemoOptions& options) {
  std::cout << "edgeland demo --physics: world 0 0 4096 4096, 200 balls and boxes, seed "
            << options.seed << '\n';
  box2d::PhysicsScenario scenario(box2d::PhysicsScenarioOptions{.seed = options.seed});
  scenario.settle(120);
  int written = 0;
  try {
    for (int frame = 0; frame < options.frames; ++frame) {
      scenario.frame();
      if (frame % options.frame_every == 0)
        write_landscape_png(scenario.land(), frame_path(options.out, written++),
                            frame_picture(scenario.scene()));
    }
  } catch (const PictureError& e) {
    std::cerr << "edgeland demo: " << e.what() << '\n';
    return kExitUnreadable;
  }
  print_summary(scenario, written);
  print_line("pictures", frame_path(options.out, 0) + " ...");
  return kExitOk;
}

}  // namespace edgeland::cli
