// `edgeland validate FILE`: reads a WKT POLYGON or MULTIPOLYGON and checks it against the
// kernel's invariants (kernel/validate.hpp). A MULTIPOLYGON is checked as a polygon set.
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::cli {
namespace {

struct ValidateOptions {
  std::string path;
  bool all = false;
};

// Holes are not part of the kernel's polygon model (polygon.hpp): a region with holes is
// several hole-free polygons, which is what the clipper's normalize produces from WKT.
bool report_holes(const WktGeometry& geometry) {
  for (std::size_t i = 0; i < geometry.polygons.size(); ++i) {
    const std::size_t holes = geometry.polygons[i].holes.size();
    if (holes == 0) continue;
    std::cout << "invalid: holes: polygon " << i << " has " << holes
              << " hole(s): holes are not part of the kernel model; use `edgeland clip` "
                 "(normalize) to import them\n";
    return true;
  }
  return false;
}

ValidationReport validate_geometry(const WktGeometry& geometry, std::size_t max_violations) {
  if (geometry.type == WktGeometry::Type::kPolygon) {
    return validate(geometry.polygons.front().exterior, max_violations);
  }
  PolygonSet set;
  set.reserve(geometry.polygons.size());
  for (const WktPolygon& polygon : geometry.polygons) set.push_back(polygon.exterior);
  return validate(set, max_violations);
}

// The first violation, and how many more the check found. It stops at kDefaultMaxViolations,
// so a full report says that there may be others beyond it.
void print_first(const ValidationReport& report) {
  std::cout << "invalid: " << report.violations.front().describe();
  const std::size_t more = report.violations.size() - 1;
  if (report.violations.size() >= kDefaultMaxViolations) {
    std::cout << " (+" << more << " more, and the check stopped there; --all lists every one)";
  } else if (more > 0) {
    std::cout << " (+" << more << " more; --all lists them)";
  }
  std::cout << '\n';
}

int run_validate(const ValidateOptions& options) {
  WktGeometry geometry;
  try {
    geometry = read_wkt(demo::read_input_text(options.path));
  } catch (const demo::InputError& error) {
    std::cerr << "edgeland validate: " << error.what() << '\n';
    return kExitUnreadable;
  } catch (const WktError& error) {
    const std::string name = options.path == "-" ? "standard input" : options.path;
    std::cerr << "edgeland validate: " << name << ": " << error.what() << '\n';
    return kExitUnreadable;
  }
  if (report_holes(geometry)) return kExitInvalid;

  // --all: no limit (each further violation costs one more sweep).
  const ValidationReport report =
      validate_geometry(geometry, options.all ? SIZE_MAX : kDefaultMaxViolations);
  if (report.ok()) {
    std::cout << "valid\n";
    return kExitOk;
  }
  if (!options.all) {
    print_first(report);
    return kExitInvalid;
  }
  for (const Violation& violation : report.violations) {
    std::cout << "invalid: " << violation.describe() << '\n';
  }
  return kExitInvalid;
}

}  // namespace

Command add_validate_command(CLI::App& parent) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* app =
      parent.add_subcommand("validate",
                            "Check a WKT POLYGON or MULTIPOLYGON (integer coordinates) against the "
                            "kernel's invariants; a MULTIPOLYGON is checked as a polygon set.");
  app->add_option("FILE", options->path, "WKT file, or - for standard input")->required();
  app->add_flag("--all", options->all, "List every violation found, one per line");
  app->footer(
      "Exit status: 0 and `valid`; 1 and `invalid: <rule>: <polygon/edge indices> at <point>` "
      "(first violation); 2 and a one-line message on stderr when the input is unreadable.");
  return {app, [options] { return run_validate(*options); }};
}

}  // namespace edgeland::cli
