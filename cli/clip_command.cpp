// `edgeland clip --op OP [--fill-rule RULE] [--check] SUBJECT CLIP`: a boolean operation on two
// WKT operands, printed as one WKT MULTIPOLYGON of CCW polygons without holes.
#include <cctype>
#include <initializer_list>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::cli {
namespace {

// IsMember has accepted the name in any case; the tables hold it in lower case.
std::string lower(std::string name) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

template <class Value>
std::vector<std::string> names_of(const std::map<std::string, Value>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.first);
  return names;
}

struct ClipCommandOptions {
  std::string op_name, fill_rule_name;  // as given; --op and --fill-rule set the enums below
  ClipOp op = ClipOp::kUnion;
  bool has_fill_rule = false;
  FillRule fill_rule = FillRule::kNonZero;
  bool check = false;
  bool stats = false;
  std::string subject_path;
  std::string clip_path;
};

// Without a fill rule an operand is read as OGC polygons (exterior minus holes, members
// united; a self-crossing ring counts for every lobe it winds around, clip.hpp
// import_polygons); with one, all its rings form a single path set filled by that rule.
// The result is a valid set: the operation need not check it again.
ValidSet operand(const WktGeometry& geometry, const ClipCommandOptions& o) {
  const ClipOptions checked{o.check};
  if (o.has_fill_rule) {
    std::vector<Ring> rings;
    for (const WktPolygon& p : geometry.polygons) {
      rings.push_back(p.exterior);
      rings.insert(rings.end(), p.holes.begin(), p.holes.end());
    }
    return normalize_to_valid_set(rings, o.fill_rule, checked).set;
  }
  std::vector<std::vector<Ring>> polygons;
  for (const WktPolygon& p : geometry.polygons) {
    std::vector<Ring> rings{p.exterior};
    rings.insert(rings.end(), p.holes.begin(), p.holes.end());
    polygons.push_back(std::move(rings));
  }
  return import_to_valid_set(polygons, checked).set;
}

int run_clip(const ClipCommandOptions& o) {
  if (o.subject_path == "-" && o.clip_path == "-") {
    std::cerr << "edgeland clip: only one operand can be read from standard input\n";
    return kExitUnreadable;
  }
  WktGeometry geometry[2];
  const std::string* paths[2] = {&o.subject_path, &o.clip_path};
  for (int i = 0; i < 2; ++i) {
    try {
      geometry[i] = read_wkt(demo::read_input_text(*paths[i]));
    } catch (const demo::InputError& error) {
      std::cerr << "edgeland clip: " << error.what() << '\n';
      return kExitUnreadable;
    } catch (const WktError& error) {
      const std::string name = *paths[i] == "-" ? "standard input" : *paths[i];
      std::cerr << "edgeland clip: " << name << ": " << error.what() << '\n';
      return kExitUnreadable;
    }
  }
  try {
    const ValidSet subject = operand(geometry[0], o);
    const ValidSet clip_set = operand(geometry[1], o);
    const ValidClipResult result = clip(o.op, subject, clip_set, ClipOptions{o.check});
    std::cout << to_wkt(result.set.polygons()) << '\n';
    if (o.stats) {
      std::cerr << "intersections " << result.stats.intersections << ", vertices snapped "
                << result.stats.vertices_snapped << ", holes split " << result.stats.holes_split
                << ", zero-area pieces dropped " << result.stats.zero_area_dropped << '\n';
    }
    return kExitOk;
  } catch (const InvalidInput& error) {
    std::cerr << "edgeland clip: " << error.what() << '\n';
    return kExitUnreadable;
  } catch (const InternalError& error) {
    std::cerr << "edgeland clip: " << error.what() << '\n';
    return kExitInternal;
  }
}

// Each value by its name.
template <class E, class Name>
std::map<std::string, E> by_name(std::initializer_list<E> values, Name name) {
  std::map<std::string, E> out;
  for (E v : values) out.emplace(name(v), v);
  return out;
}

}  // namespace

Command add_clip_command(CLI::App& parent) {
  auto o = std::make_shared<ClipCommandOptions>();
  CLI::App* app = parent.add_subcommand(
      "clip",
      "Boolean operation on two WKT POLYGON/MULTIPOLYGON operands (integer coordinates); prints "
      "the result as one WKT MULTIPOLYGON of counter-clockwise polygons without holes.");
  // Options take names only: a transformer over the enums would print their values as raw
  // bytes in --help and in its errors.
  // The names are the library's own (op_name, fill_rule_name): one table of them.
  static const auto ops =
      by_name({ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor}, op_name);
  static const auto rules =
      by_name({FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive, FillRule::kNegative},
              fill_rule_name);
  app->add_option("--op", o->op_name, "union, intersection, difference or xor")
      ->required()
      ->check(CLI::IsMember(names_of(ops), CLI::ignore_case))
      ->each([o](const std::string& name) { o->op = ops.at(lower(name)); });
  app->add_option("--fill-rule", o->fill_rule_name,
                  "Fill all rings of each operand by this rule (evenodd, nonzero, positive, "
                  "negative) instead of reading them as OGC polygons")
      ->check(CLI::IsMember(names_of(rules), CLI::ignore_case))
      ->each([o](const std::string& name) {
        o->fill_rule = rules.at(lower(name));
        o->has_fill_rule = true;
      });
  app->add_flag("--check", o->check, "Validate every intermediate and final result");
  app->add_flag("--stats", o->stats, "Print the operation's statistics to standard error");
  app->add_option("SUBJECT", o->subject_path, "WKT file, or - for standard input")->required();
  app->add_option("CLIP", o->clip_path, "WKT file, or - for standard input")->required();
  app->footer(
      "Exit status: 0 with the result on stdout; 2 and a one-line message on unreadable input; "
      "3 if a checked result failed validation (a bug: the message carries the inputs); 4 out of "
      "memory.");
  return {app, [o] { return run_clip(*o); }};
}

}  // namespace edgeland::cli
