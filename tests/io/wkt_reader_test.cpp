// The WKT reader (io/.../wkt_reader.hpp): what it returns for good text, and the typed error it
// throws for each kind of bad text, including the inputs Boost's read_wkt accepts silently
// (TOOLCHAIN.md pitfall 6).
#include "edgeland/io/wkt_reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "edgeland/kernel/point.hpp"

namespace edgeland {
namespace {

// Reads `text`, requires a WktError, checks the message is one line, and returns the error.
WktError rejection(const std::string& text) {
  try {
    read_wkt(text);
  } catch (const WktError& error) {
    const std::string message = error.what();
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return error;
  }
  ADD_FAILURE() << "accepted: " << text;
  return WktError(WktErrorKind::kSyntax, "accepted");
}

WktErrorKind rejection_kind(const std::string& text) { return rejection(text).kind; }

const Ring kSquare{{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(WktReaderAccepts, PolygonWithoutItsClosingVertex) {
  const WktGeometry g = read_wkt("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))");
  EXPECT_EQ(g.type, WktGeometry::Type::kPolygon);
  ASSERT_EQ(g.polygons.size(), 1u);
  EXPECT_EQ(g.polygons[0].exterior, kSquare);
  EXPECT_TRUE(g.polygons[0].holes.empty());
}

TEST(WktReaderAccepts, ClockwiseRingKeepsItsOrder) {
  // Orientation is validate()'s business; the reader must not silently fix it.
  const WktGeometry g = read_wkt("POLYGON ((0 0, 0 10, 10 10, 10 0, 0 0))");
  const Ring expected{{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  EXPECT_EQ(g.polygons[0].exterior, expected);
}

TEST(WktReaderAccepts, MultiPolygonMembersInOrder) {
  const WktGeometry g =
      read_wkt("MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((20 0, 30 0, 30 10, 20 0)))");
  EXPECT_EQ(g.type, WktGeometry::Type::kMultiPolygon);
  ASSERT_EQ(g.polygons.size(), 2u);
  EXPECT_EQ(g.polygons[0].exterior, kSquare);
  const Ring triangle{{20, 0}, {30, 0}, {30, 10}};
  EXPECT_EQ(g.polygons[1].exterior, triangle);
}

TEST(WktReaderAccepts, HolesSeparatelyFromTheExterior) {
  const WktGeometry g = read_wkt(
      "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2), (3 3, 4 3, 4 4, 3 3))");
  ASSERT_EQ(g.polygons.size(), 1u);
  EXPECT_EQ(g.polygons[0].exterior, kSquare);
  ASSERT_EQ(g.polygons[0].holes.size(), 2u);
  const Ring first_hole{{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  EXPECT_EQ(g.polygons[0].holes[0], first_hole);
  EXPECT_EQ(g.polygons[0].holes[1].size(), 3u);
}

TEST(WktReaderAccepts, MultiPolygonEmptyAsTheEmptySet) {
  // The kernel's writer (wkt_writer.hpp) writes the empty set this way; it must read back.
  const WktGeometry g = read_wkt("MULTIPOLYGON EMPTY");
  EXPECT_EQ(g.type, WktGeometry::Type::kMultiPolygon);
  EXPECT_TRUE(g.polygons.empty());
}

TEST(WktReaderAccepts, LineBreaksTabsAndLowerCaseKeywords) {
  // Boost's tokenizer only drops ' ': a raw '\n' before a number is a "bad lexical cast".
  const WktGeometry g = read_wkt("\n\tpolygon\r\n(\n(0\t0,\n10 0,\r\n10 10,0 10,0 0)\n)\n\n");
  EXPECT_EQ(g.polygons[0].exterior, kSquare);
}

TEST(WktReaderAccepts, CoordinatesAtTheBoundAndExplicitSigns) {
  const std::string b = std::to_string(kCoordBound);
  const WktGeometry g = read_wkt("POLYGON ((-" + b + " -" + b + ", +" + b + " -" + b + ", " + b +
                                 " " + b + ", -" + b + " -" + b + "))");
  const Ring expected{
      {-kCoordBound, -kCoordBound}, {kCoordBound, -kCoordBound}, {kCoordBound, kCoordBound}};
  EXPECT_EQ(g.polygons[0].exterior, expected);
}

TEST(WktReaderAccepts, DegenerateClosedRingsForValidateToJudge) {
  // Two points, first == last: closed, one vertex. Too few vertices is validate()'s rule.
  const WktGeometry g = read_wkt("POLYGON ((5 5, 5 5))");
  const Ring one_vertex{{5, 5}};
  EXPECT_EQ(g.polygons[0].exterior, one_vertex);
}

TEST(WktReaderRejects, EmptyInput) {
  EXPECT_EQ(rejection_kind(""), WktErrorKind::kEmptyInput);
  EXPECT_EQ(rejection_kind(" \n\t\r\n "), WktErrorKind::kEmptyInput);
}

TEST(WktReaderRejects, BinaryBytesNamingTheOffset) {
  const WktError nul = rejection(std::string("POLYGON ((0 0\0, 1 0, 1 1, 0 0))", 31));
  EXPECT_EQ(nul.kind, WktErrorKind::kNotText);
  EXPECT_NE(std::string(nul.what()).find("byte 0x00 at offset 13"), std::string::npos)
      << nul.what();
  EXPECT_EQ(rejection_kind("\xff\xfe"), WktErrorKind::kNotText);
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0))\x1b"), WktErrorKind::kNotText);
  // Non-ASCII text is not WKT either (no keyword or number can contain it).
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0)) \xc3\xa9"), WktErrorKind::kNotText);
}

TEST(WktReaderRejects, DecimalAndExponentCoordinatesWithTheirPosition) {
  const WktError decimal = rejection("POLYGON ((0 0, 1.5 0, 1 1, 0 0))");
  EXPECT_EQ(decimal.kind, WktErrorKind::kNotInteger);
  EXPECT_EQ(decimal.line, 1u);
  EXPECT_EQ(decimal.column, 16u);
  const WktError exponent = rejection("POLYGON ((0 0,\n 1e3 0, 1 1, 0 0))");
  EXPECT_EQ(exponent.kind, WktErrorKind::kNotInteger);
  EXPECT_EQ(exponent.line, 2u);
  EXPECT_EQ(exponent.column, 2u);
  for (const char* literal : {"10.", ".5", "-2.25", "1E-3", "+4e+2", "0.0"}) {
    EXPECT_EQ(rejection_kind(std::string("POLYGON ((0 0, ") + literal + " 0, 1 1, 0 0))"),
              WktErrorKind::kNotInteger)
        << literal;
  }
}

TEST(WktReaderRejects, MalformedNumbers) {
  for (const char* literal : {"0x10", "1-2", "-", "+", "1e", "1.2.3", "12abc", "--1"}) {
    EXPECT_EQ(rejection_kind(std::string("POLYGON ((0 0, ") + literal + " 0, 1 1, 0 0))"),
              WktErrorKind::kSyntax)
        << literal;
  }
  // Words where numbers belong.
  EXPECT_EQ(rejection_kind("POLYGON ((nan 0, inf 0, 1 1, nan 0))"), WktErrorKind::kSyntax);
}

TEST(WktReaderRejects, CoordinateOfTwoToTheFortyNamingTheVertex) {
  // The example: 2^40 is far outside |c| <= 2^31 - 1.
  const WktError e = rejection("POLYGON ((0 0, 10 0, 10 10, 1099511627776 10, 0 0))");
  EXPECT_EQ(e.kind, WktErrorKind::kCoordinateOutOfRange);
  EXPECT_EQ(e.polygon, 0u);
  EXPECT_EQ(e.ring, 0u);
  EXPECT_EQ(e.vertex, 3u);
  EXPECT_EQ(e.where, (Point64{1099511627776, 10}));
  EXPECT_EQ(e.line, 1u);
  EXPECT_EQ(e.column, 29u);
}

TEST(WktReaderRejects, CoordinateJustBeyondTheBoundInAHoleOfTheSecondMember) {
  const std::string over = std::to_string(-kCoordBound - 1);
  const WktError e =
      rejection("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((0 0, 9 0, 9 9, 0 0), (1 1, 2 1, " + over +
                " 2, 1 1)))");
  EXPECT_EQ(e.kind, WktErrorKind::kCoordinateOutOfRange);
  EXPECT_EQ(e.polygon, 1u);
  EXPECT_EQ(e.ring, 1u);
  EXPECT_EQ(e.vertex, 2u);
  EXPECT_EQ(e.where, (Point64{-kCoordBound - 1, 2}));
}

TEST(WktReaderRejects, CoordinatesBeyondInt64) {
  for (const char* literal : {"9223372036854775808", "-9223372036854775809", "99999999999999999999",
                              "9223372036854775807"}) {
    const WktError e = rejection(std::string("POLYGON ((0 0, ") + literal + " 0, 1 1, 0 0))");
    EXPECT_EQ(e.kind, WktErrorKind::kCoordinateOutOfRange) << literal;
    EXPECT_EQ(e.column, 16u) << literal;
  }
}

TEST(WktReaderRejects, StrayThirdCoordinate) {
  // read_wkt would read "10 0 5" as the two points (10 0) and (5 0).
  const WktError e = rejection("POLYGON ((0 0, 10 0 5, 10 10, 0 0))");
  EXPECT_EQ(e.kind, WktErrorKind::kWrongDimension);
  EXPECT_EQ(e.column, 16u);
}

TEST(WktReaderRejects, MissingYCoordinate) {
  // read_wkt would read a lone "1" as (1 0).
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 10 0, 1, 0 0))"), WktErrorKind::kWrongDimension);
}

TEST(WktReaderRejects, ZAndMQualifiers) {
  EXPECT_EQ(rejection_kind("POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))"),
            WktErrorKind::kWrongDimension);
  // read_wkt accepts "POLYGON M" with 2 numbers per point and drops the M silently.
  EXPECT_EQ(rejection_kind("POLYGON M ((0 0, 1 0, 1 1, 0 0))"), WktErrorKind::kWrongDimension);
}

TEST(WktReaderRejects, MisplacedCommasThatReadWktTurnsIntoPointsOrDrops) {
  // ",," and "(," would become a (0 0) point; a trailing comma would be dropped.
  for (const char* text :
       {"POLYGON ((0 0, 1 0,, 1 1, 0 0))", "POLYGON ((, 0 0, 1 0, 1 1, 0 0))",
        "POLYGON ((0 0, 1 0, 1 1, 0 0,))", "POLYGON ((0 0, 1 0, 1 1, 0 0),)",
        "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)),)", "POLYGON, ((0 0, 1 0, 1 1, 0 0))"}) {
    EXPECT_EQ(rejection_kind(text), WktErrorKind::kSyntax) << text;
  }
}

TEST(WktReaderRejects, MissingCommaBetweenRings) {
  // read_wkt reads "(...)(...)" as two rings.
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 9 0, 9 9, 0 0)(1 1, 2 1, 2 2, 1 1))"),
            WktErrorKind::kSyntax);
}

// OGC's empty geometries are the empty set (issue 16): POLYGON EMPTY, and EMPTY members of a
// MULTIPOLYGON, which leave the other members and their numbering as if they were absent.
TEST(WktReader, EmptyGeometriesAreTheEmptySet) {
  for (const char* text : {"POLYGON EMPTY", "polygon empty", "MULTIPOLYGON (EMPTY)",
                           "MULTIPOLYGON (EMPTY, EMPTY)", "MULTIPOLYGON EMPTY"}) {
    const WktGeometry g = read_wkt(text);
    EXPECT_EQ(g.type, WktGeometry::Type::kMultiPolygon) << text;
    EXPECT_TRUE(g.polygons.empty()) << text;
  }
  const Ring square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Ring far{{5, 5}, {6, 5}, {6, 6}};
  for (const char* text :
       {"MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 1, 0 0)), EMPTY, ((5 5, 6 5, 6 6, 5 5)))",
        "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), EMPTY, EMPTY, ((5 5, 6 5, 6 6, 5 5)), "
        "EMPTY)"}) {
    const WktGeometry g = read_wkt(text);
    ASSERT_EQ(g.polygons.size(), 2u) << text;
    EXPECT_EQ(g.polygons[0].exterior, square) << text;
    EXPECT_EQ(g.polygons[1].exterior, far) << text;
  }
  // A stray comma is still an error, EMPTY or not.
  EXPECT_EQ(rejection_kind("MULTIPOLYGON (EMPTY,, ((0 0, 1 0, 1 1, 0 0)))"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)) EMPTY)"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("POLYGON (EMPTY)"), WktErrorKind::kSyntax);
}

// A UTF-8 byte-order mark is not text; elsewhere its bytes are.
TEST(WktReader, SkipsAByteOrderMark) {
  const WktGeometry g = read_wkt("\xEF\xBB\xBFPOLYGON ((0 0, 1 0, 1 1, 0 0))");
  ASSERT_EQ(g.polygons.size(), 1u);
  EXPECT_EQ(g.polygons[0].exterior.size(), 3u);
  EXPECT_EQ(rejection_kind("POLYGON \xEF\xBB\xBF((0 0, 1 0, 1 1, 0 0))"), WktErrorKind::kNotText);
}

TEST(WktReaderRejects, EmptyGeometries) {
  EXPECT_EQ(rejection_kind("POLYGON ()"), WktErrorKind::kEmptyGeometry);
  EXPECT_EQ(rejection_kind("POLYGON (())"), WktErrorKind::kEmptyGeometry);
  EXPECT_EQ(rejection_kind("MULTIPOLYGON (())"), WktErrorKind::kEmptyGeometry);
  EXPECT_EQ(rejection_kind("MULTIPOLYGON ()"), WktErrorKind::kEmptyGeometry);
}

TEST(WktReaderRejects, UnclosedRingNamingItsLastVertex) {
  const WktError e = rejection("POLYGON ((0 0, 10 0, 10 10, 0 10))");
  EXPECT_EQ(e.kind, WktErrorKind::kUnclosedRing);
  EXPECT_EQ(e.polygon, 0u);
  EXPECT_EQ(e.ring, 0u);
  EXPECT_EQ(e.vertex, 3u);
  EXPECT_EQ(e.where, (Point64{0, 10}));
  const WktError hole = rejection("POLYGON ((0 0, 9 0, 9 9, 0 0), (1 1, 2 1, 2 2))");
  EXPECT_EQ(hole.kind, WktErrorKind::kUnclosedRing);
  EXPECT_EQ(hole.ring, 1u);
  // One point is too few to close a ring (two close one of one vertex, which validate refuses).
  EXPECT_EQ(rejection_kind("POLYGON ((1 1))"), WktErrorKind::kTooFewPoints);
  const WktError few = rejection("POLYGON ((0 0))");
  EXPECT_NE(std::string(few.what()).find("a ring needs at least 3 points"), std::string::npos)
      << few.what();
}

TEST(WktReaderRejects, OtherGeometryTypes) {
  for (const char* text :
       {"LINESTRING (0 0, 1 1)", "POINT (1 2)",
        "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)))", "POLYGONS ((0 0, 1 0, 1 1, 0 0))"}) {
    EXPECT_EQ(rejection_kind(text), WktErrorKind::kUnsupportedGeometry) << text;
  }
  EXPECT_EQ(rejection_kind("((0 0, 1 0, 1 1, 0 0))"), WktErrorKind::kSyntax);
}

TEST(WktReaderRejects, TrailingText) {
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0)) extra"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0));"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0)))"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("POLYGON ((0 0, 1 0, 1 1, 0 0)) POLYGON ((0 0, 1 0, 1 1, 0 0))"),
            WktErrorKind::kSyntax);
}

TEST(WktReaderRejects, WrongNesting) {
  EXPECT_EQ(rejection_kind("POLYGON (0 0, 1 0, 1 1, 0 0)"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("POLYGON (((0 0, 1 0, 1 1, 0 0)))"), WktErrorKind::kSyntax);
  EXPECT_EQ(rejection_kind("MULTIPOLYGON ((0 0, 1 0, 1 1, 0 0))"), WktErrorKind::kSyntax);
}

TEST(WktReaderRejects, EveryTruncationOfAValidText) {
  // A file cut short anywhere (the "truncated file") is an error, never a shorter shape.
  const std::string text =
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((20 0, 30 0, 30 10, 20 0), "
      "(21 1, 22 1, 22 2, 21 1)))";
  ASSERT_NO_THROW(read_wkt(text));
  for (std::size_t length = 0; length < text.size(); ++length) {
    const std::string prefix = text.substr(0, length);
    EXPECT_THROW(read_wkt(prefix), WktError) << "prefix: " << prefix;
  }
}

TEST(WktReaderRejects, DeepNestingWithoutRecursing) {
  const std::string deep = "POLYGON " + std::string(100000, '(') + std::string(100000, ')');
  EXPECT_THROW(read_wkt(deep), WktError);
}

TEST(WktReaderRejects, LongJunkTokenKeepsTheMessageShort) {
  const WktError e = rejection("POLYGON ((0 0, " + std::string(100000, '7') + "x 0, 1 1, 0 0))");
  EXPECT_LT(std::string(e.what()).size(), 200u);
}

TEST(WktReaderErrors, AreEdgelandErrors) {
  // Callers that handle edgeland::Error handle the reader's errors too.
  EXPECT_THROW(read_wkt("POLYGON ((0 0, 1.5 0, 1 1, 0 0))"), Error);
  EXPECT_STREQ(wkt_error_kind_name(WktErrorKind::kNotInteger), "not-integer");
}

}  // namespace
}  // namespace edgeland
