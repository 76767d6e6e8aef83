// Continuous-clip logs (io/.../clip_log.hpp): the parser's typed line errors, the OGC reading of
// `set`, the evolving set's strong guarantee and the recorder's faithful replay.
#include "edgeland/io/clip_log.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::log {
namespace {

const char* const kSquare = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))";

PolygonSet replay(const std::string& text) {
  const ParsedLog parsed = parse_log(text);
  EXPECT_FALSE(parsed.error.has_value()) << parsed.error->what();
  EvolvingSet state;
  for (const Step& step : parsed.steps) state.apply(step, ClipOptions{.checked = true});
  return state.current();
}

TEST(LogParser, ReadsEveryKeywordAndSkipsCommentsBlankLinesAndCarriageReturns) {
  const std::string text = std::string("# header\n\nset ") + kSquare + "\r\n  union " + kSquare +
                           "\t\nintersection " + kSquare + "\ndifference " + kSquare +
                           "\n   # indented comment\nxor MULTIPOLYGON EMPTY\n";
  const ParsedLog parsed = parse_log(text);
  ASSERT_FALSE(parsed.error.has_value());
  ASSERT_EQ(parsed.steps.size(), 5u);
  EXPECT_EQ(parsed.steps[0].kind, StepKind::kSet);
  EXPECT_EQ(parsed.steps[0].line, 3u);
  EXPECT_EQ(parsed.steps[1].kind, StepKind::kUnion);
  EXPECT_EQ(parsed.steps[2].kind, StepKind::kIntersection);
  EXPECT_EQ(parsed.steps[3].kind, StepKind::kDifference);
  EXPECT_EQ(parsed.steps[4].kind, StepKind::kXor);
  EXPECT_EQ(parsed.steps[4].line, 8u);
  EXPECT_TRUE(parsed.steps[4].shape.polygons.empty());
}

TEST(LogParser, UnknownKeywordIsATypedErrorNamingTheLine) {
  try {
    parse_log_line("Union POLYGON ((0 0, 1 0, 1 1, 0 0))", 7);
    FAIL() << "keywords are lower case";
  } catch (const LogError& e) {
    EXPECT_EQ(e.kind, LogErrorKind::kUnknownStep);
    EXPECT_EQ(e.line, 7u);
    EXPECT_EQ(std::string(e.what()).rfind("line 7: unknown step 'Union'", 0), 0u) << e.what();
  }
}

TEST(LogParser, KeywordWithoutShapeIsMissingShape) {
  try {
    parse_log_line("difference   ", 2);
    FAIL();
  } catch (const LogError& e) {
    EXPECT_EQ(e.kind, LogErrorKind::kMissingShape);
    EXPECT_EQ(e.line, 2u);
  }
}

TEST(LogParser, EveryErrorKindHasItsDocumentedStableName) {
  // The kinds of the errors the parser throws, named as clip_log.hpp documents ("unknown-step"
  // ...): a tool reporting them in JSON depends on these strings staying the same.
  const std::pair<const char*, const char*> lines[] = {
      {"Union POLYGON ((0 0, 1 0, 1 1, 0 0))", "unknown-step"},
      {"difference", "missing-shape"},
      {"set POLYGON ((0 0, 1.5 0, 1 1, 0 0))", "bad-shape"}};
  for (const auto& [line, name] : lines) {
    try {
      parse_log_line(line, 1);
      ADD_FAILURE() << "no error for: " << line;
    } catch (const LogError& e) {
      EXPECT_STREQ(log_error_kind_name(e.kind), name) << line;
    }
  }
}

TEST(LogParser, KeywordGluedToTheShapeIsUnknown) {
  EXPECT_THROW(parse_log_line("unionPOLYGON ((0 0, 1 0, 1 1, 0 0))", 1), LogError);
}

TEST(LogParser, BadWktKeepsTheReadersErrorKind) {
  try {
    parse_log_line("union POLYGON ((0 0, 1.5 0, 1 1, 0 0))", 4);
    FAIL();
  } catch (const LogError& e) {
    EXPECT_EQ(e.kind, LogErrorKind::kBadShape);
    ASSERT_TRUE(e.wkt_error.has_value());
    EXPECT_EQ(*e.wkt_error, WktErrorKind::kNotInteger);
  }
}

TEST(LogParser, StopsAtTheFirstBadLineKeepingTheStepsBefore) {
  const std::string text = std::string("set ") + kSquare + "\n# c\nunion " + kSquare +
                           "\nfrobnicate x\nunion " + kSquare + "\n";
  const ParsedLog parsed = parse_log(text);
  ASSERT_TRUE(parsed.error.has_value());
  EXPECT_EQ(parsed.error->line, 4u);
  EXPECT_EQ(parsed.steps.size(), 2u);
}

TEST(LogSet, WktWithAHoleIsImportedWithOgcSemantics) {
  // 10x10 minus the 2x2 hole: twice the area is 2 * 96.
  const PolygonSet state =
      replay("set POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2))\n");
  EXPECT_TRUE(validate(state).ok());
  EXPECT_EQ(twice_signed_area(state), 192);
}

TEST(LogSet, ClockwiseRingIsImportedAsItsRegion) {
  const PolygonSet state = replay("set POLYGON ((0 0, 0 10, 10 10, 10 0, 0 0))\n");
  EXPECT_TRUE(validate(state).ok());
  EXPECT_EQ(twice_signed_area(state), 200);
}

TEST(LogSet, ValidSetIsKeptVertexForVertex) {
  // Two members sharing the edge x = 10 and a collinear vertex (5 0): import_polygons would
  // merge the members and drop the vertex; a recorded state must replay exactly.
  const PolygonSet state = replay(
      "set MULTIPOLYGON (((0 0, 5 0, 10 0, 10 10, 0 10, 0 0)), ((10 0, 20 0, 20 10, 10 10, 10 "
      "0)))\n");
  const PolygonSet expected{{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}},
                            {{10, 0}, {20, 0}, {20, 10}, {10, 10}}};
  EXPECT_EQ(state, expected);
}

TEST(EvolvingSet, RejectedStepLeavesTheSetUnchanged) {
  EvolvingSet state(PolygonSet{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
  const PolygonSet before = state.current();
  const PolygonSet bowtie{{{0, 0}, {4, 4}, {4, 0}, {0, 4}}};
  EXPECT_THROW(state.apply(ClipOp::kUnion, bowtie), InvalidInput);
  EXPECT_EQ(state.current(), before);
}

TEST(EditLog, RecordedClipsOnDifferentSubjectsReplayToTheSameState) {
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const PolygonSet sliver{{{0, 0}, {10, 1}, {0, 1}}};  // crossings off the grid: snapping
  const PolygonSet other{{{20, 0}, {30, 0}, {30, 7}}};
  EditLog recorder;
  recorder.comment("test\nwith a line break");
  PolygonSet state = recorder.clip(ClipOp::kDifference, square, sliver).polygons;
  state = recorder.clip(ClipOp::kXor, state, PolygonSet{{{3, -1}, {7, 4}, {2, 9}}}).polygons;
  // Unrelated subject: the log must switch to it with a `set` line.
  const PolygonSet unrelated = recorder.clip(ClipOp::kUnion, other, square).polygons;
  EXPECT_EQ(recorder.steps(), 5u);  // set, difference, xor, then set other, union
  EXPECT_EQ(replay(recorder.text()), unrelated);
  EXPECT_EQ(recorder.text().rfind("# test with a line break\n", 0), 0u);
}

TEST(EditLog, ContinuingFromTheLastResultWritesNoSetLine) {
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  EditLog recorder;
  PolygonSet state = recorder.clip(ClipOp::kUnion, square, square).polygons;
  state = recorder.clip(ClipOp::kDifference, state, PolygonSet{{{2, 2}, {4, 2}, {4, 4}}}).polygons;
  EXPECT_EQ(recorder.steps(), 3u);  // set, union, difference
  EXPECT_EQ(replay(recorder.text()), state);
}

TEST(StateHash, IsFnv1a64OfTheStatesWkt) {
  // Published FNV-1a 64 test vectors.
  EXPECT_EQ(fnv1a64_hex(""), "cbf29ce484222325");
  EXPECT_EQ(fnv1a64_hex("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(fnv1a64_hex("foobar"), "85944171f73967e8");
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  EXPECT_EQ(state_hash(square), fnv1a64_hex(to_wkt(square)));
}

}  // namespace
}  // namespace edgeland::log
