// Landscape edit logs (io/.../landscape_log.hpp): the parser's typed line errors, the reading of
// shapes and materials, the round trip of the library's own recording (Landscape::start_log)
// through the parser to the same state_hash, and the cells Landscape::cells_in lists against
// the landscape's own cell count.
#include "edgeland/io/landscape_log.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <variant>

#include "edgeland/clip/clip.hpp"
#include "edgeland/demo/integer_trig.hpp"
#include "edgeland/io/log_kind.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/spatial/log_format.hpp"

namespace edgeland::log {
namespace {

const char* const kBox = "POLYGON ((10 10, 20 10, 20 30, 10 30, 10 10))";

LandscapeLogError error_of(std::string_view line, std::size_t number = 3) {
  try {
    parse_landscape_line(line, number);
  } catch (const LandscapeLogError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for: " << line;
  return LandscapeLogError(LandscapeLogErrorKind::kUnknownCommand, 0, "none");
}

// --- the parser ---------------------------------------------------------------------------

TEST(LandscapeLogParser, ReadsEveryCommandAndSkipsCommentsBlankLinesAndCarriageReturns) {
  const std::string text = std::string("# header\n\nworld -5 -6 100 200 7\r\n") + "carve " + kBox +
                           "\n  fill\t3 " + kBox + "  \n# between\n" +
                           "fill_empty 255 MULTIPOLYGON EMPTY\r\nreplace 0 9 " + kBox + "\n";
  const ParsedLandscapeLog parsed = parse_landscape_log(text);
  ASSERT_FALSE(parsed.error.has_value()) << parsed.error->what();
  ASSERT_TRUE(parsed.world.has_value());
  EXPECT_EQ(parsed.world->box, (Box64{{-5, -6}, {100, 200}}));
  EXPECT_EQ(parsed.world->fill, 7);
  EXPECT_EQ(parsed.world->line, 3u);
  ASSERT_EQ(parsed.edits.size(), 4u);
  EXPECT_EQ(parsed.edits[0].kind, LandscapeEditKind::kCarve);
  EXPECT_EQ(parsed.edits[0].line, 4u);
  EXPECT_EQ(parsed.edits[0].shape.polygons.front().exterior.size(), 4u);  // closing point dropped
  EXPECT_EQ(parsed.edits[1].kind, LandscapeEditKind::kFill);
  EXPECT_EQ(parsed.edits[1].material, 3);
  EXPECT_EQ(parsed.edits[2].kind, LandscapeEditKind::kFillEmpty);
  EXPECT_EQ(parsed.edits[2].material, 255);
  EXPECT_TRUE(parsed.edits[2].shape.polygons.empty());
  EXPECT_EQ(parsed.edits[3].kind, LandscapeEditKind::kReplace);
  EXPECT_EQ(parsed.edits[3].from, 0);
  EXPECT_EQ(parsed.edits[3].material, 9);
  EXPECT_EQ(parsed.edits[3].line, 8u);
}

// relabel's FROM TO pairs (issue 27, point 11): any number of them, then the shape; the
// materials not named stay.
TEST(LandscapeLogParser, RelabelReadsItsPairs) {
  const auto edit = std::get<LandscapeEdit>(
      *parse_landscape_line(std::string("relabel 1 2 2 1\t3 0 ") + kBox, 4));
  EXPECT_EQ(edit.kind, LandscapeEditKind::kRelabel);
  EXPECT_EQ(edit.map, MaterialMap().set(1, 2).set(2, 1).set(3, 0));
  EXPECT_EQ(edit.shape.polygons.size(), 1u);
  const auto none =
      std::get<LandscapeEdit>(*parse_landscape_line(std::string("relabel ") + kBox, 1));
  EXPECT_EQ(none.map, MaterialMap());
  EXPECT_STREQ(landscape_edit_keyword(LandscapeEditKind::kRelabel), "relabel");
}

TEST(LandscapeLogParser, RelabelRefusesHalfPairsRepeatsAndBadMaterials) {
  const LandscapeLogError half = error_of(std::string("relabel 1 ") + kBox);
  EXPECT_EQ(half.kind, LandscapeLogErrorKind::kBadArgument);
  EXPECT_NE(std::string(half.what()).find("relabel: TO 'POLYGON'"), std::string::npos)
      << half.what();
  const LandscapeLogError twice = error_of(std::string("relabel 1 2 1 3 ") + kBox);
  EXPECT_EQ(twice.kind, LandscapeLogErrorKind::kBadArgument);
  EXPECT_STREQ(twice.what(), "line 3: relabel: FROM 1 is given twice");
  EXPECT_EQ(error_of(std::string("relabel 1 256 ") + kBox).kind,
            LandscapeLogErrorKind::kBadArgument);
  EXPECT_EQ(error_of("relabel 1 2").kind, LandscapeLogErrorKind::kMissingShape);
}

TEST(LandscapeLogParser, WorldWithoutMaterialIsEmptyAndTheWholeBoundIsAllowed) {
  const auto world = std::get<WorldCommand>(
      *parse_landscape_line("world -2147483647 -2147483647 2147483647 2147483647", 1));
  EXPECT_EQ(world.box, (Box64{{-kCoordBound, -kCoordBound}, {kCoordBound, kCoordBound}}));
  EXPECT_EQ(world.fill, kEmpty);
}

TEST(LandscapeLogParser, UnknownAndUpperCaseCommandsAreUnknown) {
  const LandscapeLogError e = error_of(std::string("Carve ") + kBox, 7);
  EXPECT_EQ(e.kind, LandscapeLogErrorKind::kUnknownCommand);
  EXPECT_EQ(e.line, 7u);
  EXPECT_EQ(std::string(e.what()).rfind("line 7: unknown command 'Carve'", 0), 0u) << e.what();
  EXPECT_EQ(error_of(std::string("set ") + kBox).kind, LandscapeLogErrorKind::kUnknownCommand);
  EXPECT_EQ(error_of(std::string("carvePOLYGON ((0 0, 1 0, 1 1, 0 0))")).kind,
            LandscapeLogErrorKind::kUnknownCommand);
}

TEST(LandscapeLogParser, MaterialsOutside0To255AreBadArguments) {
  for (const char* line :
       {"fill 256 POLYGON ((0 0, 1 0, 1 1, 0 0))", "fill -1 POLYGON ((0 0, 1 0, 1 1, 0 0))",
        "fill +3 POLYGON ((0 0, 1 0, 1 1, 0 0))", "fill_empty 1.5 POLYGON ((0 0, 1 0, 1 1, 0 0))",
        "replace 3 POLYGON ((0 0, 1 0, 1 1, 0 0))", "fill", "replace 1", "world 0 0 10 10 256"}) {
    const LandscapeLogError e = error_of(line);
    EXPECT_EQ(e.kind, LandscapeLogErrorKind::kBadArgument) << line << ": " << e.what();
    EXPECT_EQ(e.line, 3u);
  }
  EXPECT_NE(std::string(error_of("fill 256 POLYGON ((0 0, 1 0, 1 1, 0 0))").what())
                .find("fill: material '256' is not a material number 0..255"),
            std::string::npos);
}

TEST(LandscapeLogParser, BadWorldBoxesAreBadArguments) {
  for (const char* line :
       {"world", "world 0 0 10", "world 0 0 10 x", "world 0 0 0 10", "world 0 10 10 5",
        "world 0 0 2147483648 10", "world 0 0 10 10 1 2", "world 0 0 10 10 POLYGON"}) {
    EXPECT_EQ(error_of(line).kind, LandscapeLogErrorKind::kBadArgument) << line;
  }
}

TEST(LandscapeLogParser, EditWithoutShapeIsMissingShape) {
  EXPECT_EQ(error_of("carve  ").kind, LandscapeLogErrorKind::kMissingShape);
  EXPECT_EQ(error_of("replace 1 2").kind, LandscapeLogErrorKind::kMissingShape);
}

TEST(LandscapeLogParser, BadWktKeepsTheReadersErrorKind) {
  const LandscapeLogError e = error_of("fill 1 POLYGON ((0 0, 1.5 0, 1 1, 0 0))", 4);
  EXPECT_EQ(e.kind, LandscapeLogErrorKind::kBadShape);
  ASSERT_TRUE(e.wkt_error.has_value());
  EXPECT_EQ(*e.wkt_error, WktErrorKind::kNotInteger);
  // One position, in the log's terms (issue 27, point 17: it read "line 4: fill: line 1,
  // column 16: ..."): '1.5' is column 16 of the WKT, which starts at column 8 of the line.
  EXPECT_EQ(e.column, 23u);
  EXPECT_EQ(std::string(e.what()),
            "line 4, column 23: fill: coordinate '1.5' is not an integer; only integers are "
            "accepted");
  // An error about a vertex names it, at the vertex's place in the line.
  const LandscapeLogError far = error_of("carve POLYGON ((0 0, 4294967296 0, 1 1, 0 0))", 2);
  EXPECT_EQ(std::string(far.what()),
            "line 2, column 22: carve: polygon 0 ring 0 vertex 1: coordinate (4294967296 0) is "
            "beyond the bound |c| <= 2147483647");
}

TEST(LandscapeLogParser, TheWorldComesFirstAndOnlyOnce) {
  const ParsedLandscapeLog before = parse_landscape_log(std::string("# c\ncarve ") + kBox + "\n");
  EXPECT_FALSE(before.world.has_value());
  ASSERT_TRUE(before.error.has_value());
  EXPECT_EQ(before.error->kind, LandscapeLogErrorKind::kMissingWorld);
  EXPECT_EQ(before.error->line, 2u);

  const ParsedLandscapeLog twice =
      parse_landscape_log(std::string("world 0 0 9 9\nfill 1 ") + kBox + "\nworld 0 0 9 9\n");
  ASSERT_TRUE(twice.error.has_value());
  EXPECT_EQ(twice.error->kind, LandscapeLogErrorKind::kRepeatedWorld);
  EXPECT_EQ(twice.error->line, 3u);
  EXPECT_EQ(twice.edits.size(), 1u);

  for (const char* nothing : {"", "# only a comment\n\n"}) {
    const ParsedLandscapeLog empty = parse_landscape_log(nothing);
    ASSERT_TRUE(empty.error.has_value());
    EXPECT_EQ(empty.error->kind, LandscapeLogErrorKind::kMissingWorld);
    EXPECT_EQ(empty.error->line, 1u);
  }
}

TEST(LandscapeLogParser, EveryErrorKindHasItsDocumentedStableName) {
  // The kinds of real errors, named as landscape_log.hpp documents ("missing-world" ...): a tool
  // reporting them in JSON depends on these strings staying the same, and no two are alike.
  const auto name_of = [](std::string_view text) {
    const ParsedLandscapeLog parsed = parse_landscape_log(text);
    EXPECT_TRUE(parsed.error.has_value()) << text;
    return std::string(parsed.error ? landscape_log_error_kind_name(parsed.error->kind) : "");
  };
  const std::string world = "world 0 0 9 9\n";
  EXPECT_EQ(name_of(world + "dig " + kBox), "unknown-command");
  EXPECT_EQ(name_of(std::string("carve ") + kBox), "missing-world");
  EXPECT_EQ(name_of(world + world), "repeated-world");
  EXPECT_EQ(name_of(world + "fill 256 " + kBox), "bad-argument");
  EXPECT_EQ(name_of(world + "fill 1"), "missing-shape");
  EXPECT_EQ(name_of(world + "carve POLYGON ((0 0, 1.5 0, 1 1, 0 0))"), "bad-shape");
}

TEST(LandscapeLogFormat, AnEditsLineIsTheLineTheLandscapeRecordsForIt) {
  // log_format.hpp's writer of a batch's Edit and the landscape's own recorder write one
  // format: applying each edit to a recording landscape appends exactly edit_line(edit), and
  // the reader takes it back as the same kind.
  const ValidSet box(PolygonSet{{{10, 10}, {20, 10}, {20, 30}, {10, 30}}});
  const Edit edits[] = {Edit::carve(box), Edit::fill(box, 3), Edit::fill_empty(box, 5),
                        Edit::replace(box, 3, 7),
                        Edit::relabel(box, MaterialMap().set(7, 2).set(2, 7))};
  Landscape world({{0, 0}, {100, 50}}, 1);
  world.start_log();
  for (const Edit& edit : edits) {
    const std::string before = world.log();
    edgeland::apply_edit(world, edit);
    const std::string line = edit_line(edit);
    EXPECT_EQ(world.log(), before + line);
    const std::optional<LandscapeCommand> read =
        parse_landscape_line(line.substr(0, line.size() - 1), 1);
    ASSERT_TRUE(read && std::holds_alternative<LandscapeEdit>(*read)) << line;
    EXPECT_EQ(std::get<LandscapeEdit>(*read).kind, edit.kind) << line;
  }
}

TEST(LandscapeLogParser, StopsAtTheFirstBadLineKeepingTheEditsBefore) {
  const std::string text = std::string("world 0 0 99 99\nfill 1 ") + kBox + "\ncarve " + kBox +
                           "\nfill 300 " + kBox + "\ncarve " + kBox + "\n";
  const ParsedLandscapeLog parsed = parse_landscape_log(text);
  ASSERT_TRUE(parsed.error.has_value());
  EXPECT_EQ(parsed.error->line, 4u);
  EXPECT_EQ(parsed.edits.size(), 2u);
}

TEST(LandscapeLogKind, TheFirstCommandWorldMakesALandscapeLog) {
  EXPECT_TRUE(is_landscape_log("# comment\n\n  world 0 0 1 1\n"));
  EXPECT_TRUE(is_landscape_log("world junk"));  // a landscape log with a bad world line
  EXPECT_FALSE(is_landscape_log(std::string("set ") + kBox));
  EXPECT_FALSE(is_landscape_log(std::string("carve ") + kBox + "\nworld 0 0 1 1"));
  EXPECT_FALSE(is_landscape_log("worldly 0 0 1 1"));
  EXPECT_FALSE(is_landscape_log(""));
}

// log_kind.hpp (issue 27, point 17): no command and an unknown first command are neither kind
// of log, and the one line about them names what both kinds start with.
TEST(LandscapeLogKind, TextsThatAreNeitherKindOfLogSaySo) {
  EXPECT_EQ(log_start("# c\n\n world 0 0 1 1").kind, LogKind::kLandscape);
  EXPECT_EQ(log_start("# c\n\n world 0 0 1 1").line, 3u);
  EXPECT_EQ(log_start(std::string("xor ") + kBox).kind, LogKind::kClip);
  EXPECT_FALSE(log_start_problem(log_start(std::string("set ") + kBox)).has_value());
  const LogStart none = log_start("# only\n  \n# comments\r\n");
  EXPECT_EQ(none.kind, LogKind::kNoCommand);
  EXPECT_EQ(log_start_problem(none)->rfind("no command: ", 0), 0u);
  const LogStart junk = log_start("\n carve " + std::string(kBox));
  EXPECT_EQ(junk.kind, LogKind::kUnknown);  // an edit before any world line
  EXPECT_EQ(*log_start_problem(junk),
            "line 2: unknown command 'carve' (a landscape log starts with `world X0 Y0 X1 Y1 "
            "[MATERIAL]`, a continuous-clip log with a step: set, union, intersection, "
            "difference or xor)");
}

// --- applying edits -----------------------------------------------------------------------

Landscape replay(const std::string& text) {
  const ParsedLandscapeLog parsed = parse_landscape_log(text);
  EXPECT_FALSE(parsed.error.has_value()) << parsed.error->what();
  Landscape landscape = make_landscape(*parsed.world);
  landscape.set_checked(true);
  for (const LandscapeEdit& edit : parsed.edits) apply_edit(landscape, edit);
  return landscape;
}

TEST(LandscapeLogApply, AreasOfAxisAlignedEditsAreThoseWorkedOutByHand) {
  const Landscape l = replay(
      "world 0 0 100 50\n"
      "fill 1 POLYGON ((10 10, 20 10, 20 30, 10 30, 10 10))\n"         // 1: 200
      "fill_empty 2 POLYGON ((15 10, 40 10, 40 20, 15 20, 15 10))\n"   // 2: [20,40]x[10,20] 200
      "replace 1 3 POLYGON ((0 0, 15 0, 15 100, 0 100, 0 0))\n"        // 3: 100, 1: 100
      "fill 0 POLYGON ((35 0, 60 0, 60 60, 35 60, 35 0))\n"            // fill 0 carves: 2: 150
      "replace 0 4 POLYGON ((35 10, 45 10, 45 20, 35 20, 35 10))\n");  // 4: all empty there: 100
  EXPECT_EQ(l.twice_area(1), 200);
  EXPECT_EQ(l.twice_area(2), 300);
  EXPECT_EQ(l.twice_area(3), 200);
  EXPECT_EQ(l.twice_area(4), 200);
  EXPECT_EQ(l.twice_area(kEmpty), 2 * 100 * 50 - 900);
  EXPECT_TRUE(l.check().ok());
}

TEST(LandscapeLogApply, ShapeThatIsNotAValidSetIsImportedWithOgcSemantics) {
  // The bow-tie (0 0)-(10 10)-(10 0)-(0 10) winds around both lobes, triangles of area 25.
  const Landscape bowtie =
      replay("world 0 0 20 20\nfill 1 POLYGON ((0 0, 10 10, 10 0, 0 10, 0 0))\n");
  EXPECT_EQ(bowtie.twice_area(1), 100);
  // A hole is subtracted, whatever the rings' orientations: 400 - 100.
  const Landscape holed = replay(
      "world 0 0 40 40\nfill 2 POLYGON ((0 0, 0 20, 20 20, 20 0, 0 0), (5 5, 15 5, 15 15, 5 15, 5 "
      "5))\n");
  EXPECT_EQ(holed.twice_area(2), 600);
}

TEST(LandscapeLogApply, WorldMaterialFillsTheWorld) {
  const Landscape l = replay("world 0 0 30 10 4\ncarve POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))\n");
  EXPECT_EQ(l.twice_area(4), 400);
  EXPECT_EQ(l.twice_area(kEmpty), 200);
}

// --- the library's recording read back -----------------------------------------------------

// A ring of n points around c with radii in [r/2, r] from the integer table: rough enough to
// snap, many-sided enough to split cells (edge_cap 128) and small enough to merge them again.
Ring random_ring(edgeland::SplitMix64& random, const Box64& area) {
  const Point64 c{random.between(area.min.x, area.max.x), random.between(area.min.y, area.max.y)};
  const std::int64_t r = random.between(3, 120);
  const int n = static_cast<int>(random.between(3, 40));
  Ring ring;
  for (int i = 0; i < n; ++i) {
    ring.push_back(demo::polar(c, r * random.between(50, 100) / 100, i * demo::kFullTurn / n));
  }
  return ring;
}

// `count` random edits of every kind (materials 0..6, so fill 0 and replace from or to 0 too;
// relabels of random maps of 0..6),
// each shape a valid set made by the OGC import; some reach past the world box.
void random_edits(Landscape& l, std::uint64_t seed, int count) {
  edgeland::SplitMix64 random(seed);
  const Box64 area{{l.world().min.x - 50, l.world().min.y - 50},
                   {l.world().max.x + 50, l.world().max.y + 50}};
  for (int i = 0; i < count; ++i) {
    std::vector<std::vector<Ring>> rings{{random_ring(random, area)}};
    if (random.chance(20)) rings.push_back({random_ring(random, area)});
    const PolygonSet shape = import_polygons(rings).polygons;
    const auto kind = static_cast<LandscapeEditKind>(random.between(0, 4));
    const auto material = static_cast<Material>(random.between(0, 6));
    const auto from = static_cast<Material>(random.between(0, 6));
    if (kind != LandscapeEditKind::kRelabel) {
      apply_edit(l, kind, shape, material, from);
      continue;
    }
    MaterialMap map;
    for (int m = 0; m < 7; ++m) map.set(m, static_cast<Material>(random.between(0, 6)));
    l.relabel(shape, map);
  }
}

TEST(LandscapeLogRoundTrip, RecordedLogReplaysToTheSameStateHash) {
  Landscape recorded({{0, 0}, {1000, 600}}, 2);
  recorded.set_checked(true);
  recorded.start_log();
  random_edits(recorded, 15, 400);
  const std::string text = recorded.log();
  EXPECT_EQ(text.rfind("world 0 0 1000 600 2\n", 0), 0u);
  ASSERT_GT(recorded.stats().cells, 4u) << "the sequence should split cells";

  const ParsedLandscapeLog parsed = parse_landscape_log(text);
  ASSERT_FALSE(parsed.error.has_value()) << parsed.error->what();
  EXPECT_EQ(parsed.edits.size(), 400u);
  const Landscape replayed = replay(text);
  EXPECT_EQ(replayed.state_hash(), recorded.state_hash());
  for (int m = 0; m < 8; ++m) {
    EXPECT_EQ(replayed.twice_area(static_cast<Material>(m)),
              recorded.twice_area(static_cast<Material>(m)));
  }
}

TEST(LandscapeLogRoundTrip, LogStartedAfterEditsReplaysToTheSameRegions) {
  // start_log() on an edited landscape writes the world and one fill per material: the same
  // regions (areas, materials at every point), though not the same cells and ids.
  Landscape l({{-300, -200}, {300, 200}});
  random_edits(l, 99, 150);
  l.start_log();
  const Landscape replayed = replay(l.log());
  for (int m = 0; m < 8; ++m) {
    EXPECT_EQ(replayed.twice_area(static_cast<Material>(m)), l.twice_area(static_cast<Material>(m)))
        << "material " << m;
  }
  for (std::int64_t x = -300; x < 300; x += 7) {
    for (std::int64_t y = -200; y < 200; y += 5) {
      ASSERT_EQ(replayed.material_at({x, y}), l.material_at({x, y})) << x << " " << y;
    }
  }
}

// --- the cells (Landscape::cells_in), as --cells draws them ---------------------------------

std::vector<Box64> cells_of(const Landscape& l) {
  std::vector<Box64> out;
  l.cells_in(l.world(), [&](const CellView& c) {
    out.push_back(c.box);
    return true;
  });
  return out;
}

TEST(LandscapeCells, TileTheWorldAfterSplitsAndMerges) {
  Landscape l({{0, 0}, {800, 800}});
  random_edits(l, 7, 300);
  // Carve everything: the cells merge back towards the root.
  l.carve(PolygonSet{{{0, 0}, {800, 0}, {800, 800}, {0, 800}}});
  random_edits(l, 8, 100);
  struct Cells {
    std::vector<Box64> list;
    const std::vector<Box64>& cells() const { return list; }
  } cells{cells_of(l)};

  EXPECT_EQ(cells.cells().size(), l.stats().cells);
  // The boxes tile the world: disjoint interiors and areas summing to the world's.
  std::int64_t area = 0;
  std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t>> boxes;
  for (const Box64& b : cells.cells()) {
    area += (b.max.x - b.min.x) * (b.max.y - b.min.y);
    boxes.insert({b.min.x, b.min.y, b.max.x, b.max.y});
  }
  EXPECT_EQ(area, 800 * 800);
  EXPECT_EQ(boxes.size(), cells.cells().size());
  for (std::size_t i = 0; i < cells.cells().size(); ++i) {
    for (std::size_t j = i + 1; j < cells.cells().size(); ++j) {
      const Box64& a = cells.cells()[i];
      const Box64& b = cells.cells()[j];
      ASSERT_FALSE(a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y &&
                   b.min.y < a.max.y);
    }
  }
  // Every polygon's cell is one of them.
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    EXPECT_TRUE(boxes.count({v.cell.min.x, v.cell.min.y, v.cell.max.x, v.cell.max.y}));
    return true;
  });
}

}  // namespace
}  // namespace edgeland::log
