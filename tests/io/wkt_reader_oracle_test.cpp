// io/'s WKT reader against the reader edgeland used before it (Boost.Geometry's read_wkt behind
// the same lexical and ring checks, tests/support/wkt_reference/): on every text both accept
// exactly the same texts and read them into exactly the same rings. The new reader has its own
// parser so that io/ depends on nothing but edgeland (issue 27, point 13); this is what says the
// parser is the old reader's grammar.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "boost_wkt_reader.hpp"
#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland {
namespace {

bool same(const WktGeometry& a, const WktGeometry& b) {
  if (a.type != b.type || a.polygons.size() != b.polygons.size()) return false;
  for (std::size_t i = 0; i < a.polygons.size(); ++i) {
    if (a.polygons[i].exterior != b.polygons[i].exterior) return false;
    if (a.polygons[i].holes != b.polygons[i].holes) return false;
  }
  return true;
}

template <class Read>
std::optional<WktGeometry> outcome(Read read, const std::string& text) {
  try {
    return read(text);
  } catch (const WktError&) {
    return std::nullopt;
  }
}

// "" when both readers agree on `text`, else what differs.
std::string disagreement(const std::string& text) {
  const auto ours = outcome([](const std::string& t) { return read_wkt(t); }, text);
  const auto theirs =
      outcome([](const std::string& t) { return wkt_reference::read_wkt_with_boost(t); }, text);
  if (ours.has_value() != theirs.has_value())
    return std::string(ours ? "only io/ accepts: " : "only the Boost reader accepts: ") + text;
  if (ours && !same(*ours, *theirs)) return "read differently: " + text;
  return "";
}

// Texts made of WKT's own tokens, so that most reach the parser rather than the byte filter.
rc::Gen<std::string> wkt_like_text() {
  const auto token = rc::gen::element<std::string>(
      "POLYGON", "MULTIPOLYGON", "EMPTY", "(", "(", "(", ")", ")", ")", ",", ",", "0", "1", "-7",
      "10", "2147483647", "2147483648", " ", "  ", "Z", "1.5");
  return rc::gen::map(rc::gen::container<std::vector<std::string>>(token),
                      [](const std::vector<std::string>& parts) {
                        std::string out;
                        for (const std::string& p : parts) out += p + " ";
                        return out;
                      });
}

RC_GTEST_PROP(WktReaderOracle, AgreesOnTokenSoup, ()) {
  const std::string text = *wkt_like_text();
  RC_ASSERT(disagreement(text).empty());
  RC_ASSERT(disagreement("POLYGON " + text).empty());
  RC_ASSERT(disagreement("MULTIPOLYGON (" + text).empty());
}

TEST(WktReaderOracle, AgreesOnAStrayCommaAfterAnEmptyMember) {
  // Found by AgreesOnTokenSoup (seed 2579270481056419704): the reference dropped the comma with
  // the EMPTY member and read "MULTIPOLYGON (EMPTY , )" as the empty set; both refuse it now.
  for (const char* text : {"MULTIPOLYGON (EMPTY , ) ", "MULTIPOLYGON (EMPTY, )",
                           "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), EMPTY, )"}) {
    EXPECT_EQ(disagreement(text), "");
    EXPECT_THROW(read_wkt(text), WktError) << text;
  }
}

// A valid text with one token inserted, removed or replaced: the defects a file has in practice.
RC_GTEST_PROP(WktReaderOracle, AgreesOnValidTextsWithOneEdit, ()) {
  const std::string valid =
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), EMPTY, ((20 0, 30 0, 30 10, 20 0), "
      "(21 1, 22 1, 22 2, 21 1)))";
  std::string text = valid;
  const auto at = *rc::gen::inRange<std::size_t>(0, text.size());
  const auto piece = *rc::gen::element<std::string>("(", ")", ",", " ", "0", "7 ", "EMPTY", "");
  const auto kind = *rc::gen::inRange(0, 3);
  if (kind == 0) text.insert(at, piece);
  if (kind == 1) text.erase(at, *rc::gen::inRange<std::size_t>(1, 6));
  if (kind == 2) text.replace(at, 1, piece);
  RC_ASSERT(disagreement(text).empty());
}

RC_GTEST_PROP(WktReaderOracle, AgreesOnWhatTheKernelWrites, ()) {
  const auto coordinate = rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-3, 4),
                                         rc::gen::element(-kCoordBound - 1, kCoordBound));
  const auto ring = rc::gen::nonEmpty(
      rc::gen::container<Ring>(rc::gen::construct<Point64>(coordinate, coordinate)));
  RC_ASSERT(disagreement(to_wkt(*rc::gen::container<PolygonSet>(ring))).empty());
}

TEST(WktReaderOracle, AgreesOnEveryTruncationAndTheFuzzSeeds) {
  const std::string text =
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((20 0, 30 0, 30 10, 20 0), "
      "(21 1, 22 1, 22 2, 21 1)))";
  for (std::size_t length = 0; length <= text.size(); ++length)
    EXPECT_EQ(disagreement(text.substr(0, length)), "");
  // The parse fuzzer's seeds: hand-written WKT and logs (each line of a log on its own too).
  const std::filesystem::path seeds =
      std::filesystem::path(EDGELAND_SOURCE_DIR) / "fuzz/corpus/parse";
  std::size_t checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    EXPECT_EQ(disagreement(bytes.str()), "") << entry.path();
    std::istringstream lines(bytes.str());
    for (std::string line; std::getline(lines, line); ++checked) {
      const std::size_t space = line.find(' ');
      if (space != std::string::npos) {
        EXPECT_EQ(disagreement(line.substr(space + 1)), "");
      }
    }
  }
  EXPECT_GT(checked, 10u);
}

}  // namespace
}  // namespace edgeland
