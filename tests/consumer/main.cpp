// Uses the installed headers and libraries: an exact orientation, validate() on a square and
// on the same square clockwise, the WKT writer, a landscape, Int128 text and a typed error.
// Exit status 0 when all agree.
#include <edgeland/clip/clip.hpp>
#include <edgeland/kernel/int128.hpp>
#include <edgeland/kernel/point.hpp>
#include <edgeland/kernel/polygon.hpp>
#include <edgeland/kernel/predicates.hpp>
#include <edgeland/kernel/validate.hpp>
#include <edgeland/kernel/wkt_writer.hpp>
#include <edgeland/spatial/landscape.hpp>
#include <iostream>

int main() {
  using namespace edgeland;
  int failures = 0;
  auto check = [&failures](bool ok, const char* what) {
    if (!ok) {
      std::cerr << "consumer: FAILED: " << what << '\n';
      ++failures;
    }
  };

  // Left turn at the far corners of the coordinate range: exact, no overflow.
  const Point64 a{-kCoordBound, -kCoordBound};
  const Point64 b{kCoordBound, -kCoordBound};
  const Point64 c{kCoordBound, kCoordBound};
  check(orientation(a, b, c) == Orientation::kCounterClockwise, "orientation(a, b, c) is CCW");
  check(orientation(a, c, b) == Orientation::kClockwise, "orientation(a, c, b) is CW");

  const Polygon square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  check(validate(square).ok(), "the CCW square is valid");
  const Polygon clockwise(square.rbegin(), square.rend());
  const ValidationReport report = validate(clockwise);
  check(!report.ok() && report.violations.front().rule == Rule::kNotCounterClockwise,
        "the clockwise square breaks the counter-clockwise rule");
  check(to_wkt(square) == "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))", "to_wkt(square)");

  // The landscape: carve a square out of a filled world, query it.
  Landscape world({{0, 0}, {100, 100}}, 1);
  const ChangeSet changes = world.carve(PolygonSet{{{40, 40}, {60, 40}, {60, 60}, {40, 60}}});
  check(!changes.added.empty() && changes.removed.size() == 1,
        "the carve replaced the world's polygon");
  check(world.twice_area(1) == 2 * (10000 - 400), "the carved area is exact");
  check(world.material_at({50, 50}) == kEmpty && world.material_at({10, 10}) == 1, "material_at");

  check(to_string(world.twice_area(1)) == "19200", "to_string(Int128)");

  // A typed error from the installed headers: an inverted box keeps the box.
  const Box64 inverted{{5, 0}, {0, 5}};
  try {
    clip_to_box(PolygonSet{square}, inverted);
    check(false, "clip_to_box refuses an inverted box");
  } catch (const InvalidBox& e) {
    check(e.box == inverted && e.violation.rule == Rule::kInvertedBox, "InvalidBox keeps the box");
  }

  if (failures == 0) std::cout << "consumer: ok\n";
  return failures == 0 ? 0 : 1;
}
