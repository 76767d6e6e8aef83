// The replay of a landscape log as a library call (io/.../landscape_replay.hpp; issue 27, point
// 13): the world it builds is the one the same edits build by hand, its JSON is what `edgeland
// replay` prints (the browser playground returns the same object), and a log that stops early
// keeps the edits before the bad line and says where and why.
#include "edgeland/io/landscape_replay.hpp"

#include <gtest/gtest.h>

#include <string>

#include "edgeland/io/landscape_log.hpp"

namespace edgeland::log {
namespace {

// Worked out by hand: 1 fills [10,20]x[10,30]; 2 the empty part of [15,40]x[10,20], i.e.
// [20,40]x[10,20]; 3 takes 1's part left of x = 15; the carve takes [35,40]x[10,20] from 2; 4
// fills [70,90]x[10,25]. Four rectangles: 1 [15,20]x[10,30] (area 100), 2 [20,35]x[10,20] (150),
// 3 [10,15]x[10,30] (100), 4 (300); empty space 5000 - 650 = 4350. Twice each in the JSON.
const std::string kLog =
    "# five edits\n"
    "world 0 0 100 50\n"
    "fill 1 POLYGON ((10 10, 20 10, 20 30, 10 30, 10 10))\n"
    "fill_empty 2 POLYGON ((15 10, 40 10, 40 20, 15 20, 15 10))\n"
    "replace 1 3 POLYGON ((0 0, 15 0, 15 100, 0 100, 0 0))\n"
    "carve POLYGON ((35 0, 60 0, 60 60, 35 60, 35 0))\n"
    "fill 4 POLYGON ((70 10, 90 10, 90 25, 70 25, 70 10))\n";

// The JSON without its timing, which differs from run to run.
std::string untimed_json(const LandscapeReplay& replay) {
  std::string json = replay_json(replay);
  const std::size_t at = json.find(",\"edits_per_second\":");
  if (at == std::string::npos) return json;
  const std::size_t end = json.find_first_of(",}", at + 1);
  return json.erase(at, end - at);
}

TEST(LandscapeReplay, BuildsTheWorldTheSameEditsBuildByHand) {
  const LandscapeReplay replay = replay_landscape_log(kLog);
  ASSERT_FALSE(replay.failure.has_value()) << replay.failure->message;
  ASSERT_TRUE(replay.landscape.has_value());
  EXPECT_EQ(replay.edits, 5u);
  Landscape by_hand({{0, 0}, {100, 50}});
  by_hand.fill(PolygonSet{{{10, 10}, {20, 10}, {20, 30}, {10, 30}}}, 1);
  by_hand.fill_empty(PolygonSet{{{15, 10}, {40, 10}, {40, 20}, {15, 20}}}, 2);
  by_hand.replace(PolygonSet{{{0, 0}, {15, 0}, {15, 100}, {0, 100}}}, 1, 3);
  by_hand.carve(PolygonSet{{{35, 0}, {60, 0}, {60, 60}, {35, 60}}});
  by_hand.fill(PolygonSet{{{70, 10}, {90, 10}, {90, 25}, {70, 25}}}, 4);
  EXPECT_EQ(replay.landscape->state_hash(), by_hand.state_hash());
  EXPECT_EQ(untimed_json(replay),
            "{\"edits\":5,\"polygons\":4,\"vertices\":16,\"cells\":1,\"depth\":0,\"area\":{\"0\":"
            "\"8700\",\"1\":\"200\",\"2\":\"300\",\"3\":\"200\",\"4\":\"600\"},\"state_hash\":\"" +
                state_hash_hex(by_hand.state_hash()) + "\"}");
}

TEST(LandscapeReplay, ARecordedLogReplaysToTheSameState) {
  Landscape l({{-500, -500}, {500, 500}}, 1);
  l.start_log();
  for (int i = 0; i < 12; ++i) {
    const std::int64_t x = -400 + 70 * i;
    l.carve(PolygonSet{{{x, -30}, {x + 50, -20}, {x + 40, 60}, {x - 5, 40}}});
    l.fill(PolygonSet{{{x, 100}, {x + 30, 100}, {x + 15, 130}}}, 2 + i % 3);
  }
  const LandscapeReplay replay = replay_landscape_log(l.log(), {.check = true});
  ASSERT_FALSE(replay.failure.has_value()) << replay.failure->message;
  EXPECT_EQ(replay.edits, 24u);
  EXPECT_EQ(replay.landscape->state_hash(), l.state_hash());
  EXPECT_TRUE(replay.landscape->checked());
}

// A replay asked to record its log (a log loaded to be edited further and shared again) gives
// back a log that replays bit for bit, its own edits and the later ones too; without the option
// it records nothing.
TEST(LandscapeReplay, RecordsItsOwnLogWhenAsked) {
  const LandscapeReplay plain = replay_landscape_log(kLog);
  ASSERT_TRUE(plain.landscape.has_value());
  EXPECT_FALSE(plain.landscape->logging());
  LandscapeReplay recorded = replay_landscape_log(kLog, {.record_log = true});
  ASSERT_FALSE(recorded.failure.has_value()) << recorded.failure->message;
  Landscape& world = *recorded.landscape;
  EXPECT_TRUE(world.logging());
  world.carve(PolygonSet{{{5, 5}, {95, 5}, {95, 8}, {5, 8}}});
  const LandscapeReplay again = replay_landscape_log(world.log());
  ASSERT_FALSE(again.failure.has_value()) << again.failure->message;
  EXPECT_EQ(again.edits, recorded.edits + 1);
  EXPECT_EQ(again.landscape->state_hash(), world.state_hash());
}

TEST(LandscapeReplay, ABadLineKeepsTheEditsBeforeIt) {
  const LandscapeReplay replay = replay_landscape_log(
      "world 0 0 100 100\nfill 1 POLYGON ((0 0, 10 0, 10 10, 0 0))\n"
      "fill 256 POLYGON ((0 0, 10 0, 10 10, 0 0))\ncarve MULTIPOLYGON EMPTY\n");
  ASSERT_TRUE(replay.failure.has_value());
  EXPECT_EQ(replay.failure->kind, ReplayFailure::Kind::kUnreadable);
  EXPECT_EQ(replay.failure->line, 3u);
  EXPECT_EQ(replay.edits, 1u);
  EXPECT_EQ(replay.landscape->twice_area(1), 100);
  const std::string json = untimed_json(replay);
  EXPECT_EQ(json.substr(json.find("\"stopped_at_line\"")),
            "\"stopped_at_line\":3,\"error\":\"line 3: fill: material '256' is not a material "
            "number 0..255\"}");
}

TEST(LandscapeReplay, AShapeTheKernelRefusesStopsTheReplayAtItsLine) {
  const LandscapeReplay replay = replay_landscape_log(
      "world 0 0 100 100\ncarve POLYGON ((0 0, 10 0, 10 10, 0 0))\n"
      "fill 1 POLYGON ((0 0, 1 0, 1 1, 0 0), (0 0, 1 0, 1 1, 0 0), (-5 0, 2147483648 0, 1 1, -5 "
      "0))\n");
  ASSERT_TRUE(replay.failure.has_value());
  EXPECT_EQ(replay.failure->line, 3u);
  EXPECT_EQ(replay.edits, 1u);
  EXPECT_EQ(replay.failure->kind, ReplayFailure::Kind::kUnreadable);
}

TEST(LandscapeReplay, ABadWorldLineLeavesNoWorld) {
  const LandscapeReplay replay = replay_landscape_log("world 10 0 0 10\n");
  EXPECT_FALSE(replay.landscape.has_value());
  EXPECT_EQ(replay_json(replay),
            "{\"edits\":0,\"stopped_at_line\":1,\"error\":\"line 1: world: the box needs X0 < X1 "
            "and Y0 < Y1\"}");
}

// Whatever bytes a log holds, the JSON is valid: quotes, backslashes, control characters and
// bytes beyond ASCII are escaped.
TEST(LandscapeReplay, TheJsonEscapesAnyBytesOfTheError) {
  LandscapeReplay replay;
  replay.failure = ReplayFailure{ReplayFailure::Kind::kUnreadable, 2, "a \"b\" \\ \t\x01\xc3\xa9"};
  EXPECT_EQ(replay_json(replay),
            "{\"edits\":0,\"stopped_at_line\":2,\"error\":\"a \\\"b\\\" \\\\ "
            "\\u0009\\u0001\\u00c3\\u00a9\"}");
}

TEST(LandscapeReplay, EditsPerSecondIsAnIntegerFromTheTimeTaken) {
  LandscapeReplay replay = replay_landscape_log(kLog);
  replay.edit_time = std::chrono::milliseconds(2);
  const std::string json = replay_json(replay);
  EXPECT_NE(json.find(",\"edits_per_second\":2500}"), std::string::npos) << json;
}

}  // namespace
}  // namespace edgeland::log
