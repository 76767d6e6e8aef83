// Landscape::load on files broken in one place each, below the fields the save file codec
// writes (tests/support/save_file.hpp): bytes after the tree, a tree cut short, a varint past 64
// bits, a count past the file, an unknown node tag, coordinates past the bound, an id twice, and
// the stream itself failing or passing the limits. Each is refused with a LoadError naming what is
// wrong (spatial/src/load.cpp), with the checksum made right first: it is no defence.
#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>

#include "edgeland/spatial/landscape.hpp"
#include "save_file.hpp"

namespace edgeland::test {
namespace {

using fuzz::SavedNode;
using fuzz::SavedPolygon;
using fuzz::SaveFile;

constexpr std::size_t kHeader = 8 + 4 + 21 + 32 + 8;  // save_format.hpp: up to the tree

std::string checksummed(std::string body) {
  const std::uint64_t sum = fuzz::save_checksum(body);
  for (int i = 0; i < 8; ++i) body.push_back(static_cast<char>((sum >> (8 * i)) & 0xff));
  return body;
}

// A file's bytes without its checksum.
std::string body_of(const SaveFile& f) {
  const std::string bytes = fuzz::encode_save(f);
  return bytes.substr(0, bytes.size() - 8);
}

std::string load_error(const std::string& bytes, const LandscapeLimits& limits = {}) {
  std::istringstream in(bytes);
  try {
    Landscape::load(in, limits);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "loaded";
  return "";
}

bool says(const std::string& what, const std::string& part) {
  return what.find(part) != std::string::npos;
}

SavedPolygon square(std::uint64_t id, std::int64_t x, std::int64_t y, std::int64_t side) {
  return {id, 1, {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}};
}

// One cell of the 1024 x 1024 world with one square.
SaveFile one_square() {
  SaveFile f;
  f.next_id = 2;
  SavedNode cell;
  cell.polygons.push_back(square(1, 10, 10, 20));
  f.nodes.push_back(cell);
  return f;
}

TEST(LoadRefuses, BytesAfterTheTree) {
  const std::string good = body_of(one_square());
  std::istringstream in(checksummed(good));
  EXPECT_EQ(Landscape::load(in).stats().polygons, 1u);
  EXPECT_TRUE(says(load_error(checksummed(good + '\0')), "bytes left after the tree"));
}

TEST(LoadRefuses, ATreeCutShort) {
  // The header alone: the root's tag is missing.
  EXPECT_TRUE(says(load_error(checksummed(body_of(one_square()).substr(0, kHeader))), "truncated"));
  // An inner root with no room for its four children.
  EXPECT_TRUE(says(load_error(checksummed(body_of(one_square()).substr(0, kHeader) + '\1')),
                   "truncated tree"));
  // A polygon's vertex count promising more than is left.
  SaveFile f = one_square();
  std::string body = body_of(f);
  body.resize(body.size() - 2);  // the last vertex's two deltas
  EXPECT_TRUE(says(load_error(checksummed(body)), "count larger than the file"));
}

TEST(LoadRefuses, AnUnknownNodeTag) {
  std::string body = body_of(one_square());
  body[kHeader] = '\2';
  EXPECT_TRUE(says(load_error(checksummed(body)), "unknown node tag"));
}

// A varint's tenth byte may hold only bit 63.
TEST(LoadRefuses, AVarintPast64Bits) {
  std::string body = body_of(one_square()).substr(0, kHeader + 1);  // the root cell's tag
  body += std::string(9, '\xff');
  body += '\x02';
  EXPECT_TRUE(says(load_error(checksummed(body)), "varint overflows 64 bits"));
  // 2^63 itself reads (and is then refused as a count).
  std::string top = body_of(one_square()).substr(0, kHeader + 1);
  top += std::string(9, '\x80');
  top += '\x01';
  EXPECT_TRUE(says(load_error(checksummed(top)), "count larger than the file"));
}

TEST(LoadRefuses, APolygonOfMaterialZero) {
  SaveFile f = one_square();
  f.nodes[0].polygons[0].material = 0;
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "a polygon of material 0"));
}

TEST(LoadRefuses, IdsOutsideOneToTheNextIdOrTwice) {
  SaveFile f = one_square();
  f.nodes[0].polygons[0].id = 0;
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "polygon id 0 not in 1..next id - 1"));
  // The same id in two cells of a split world (28 vertices: more than merge_below).
  SaveFile split;
  split.next_id = 8;
  split.nodes.push_back(SavedNode{true, {}});
  for (int i = 0; i < 4; ++i) split.nodes.push_back(SavedNode{});
  split.nodes[1].polygons.push_back(square(3, 10, 10, 20));
  split.nodes[2].polygons.push_back(square(3, 522, 10, 20));
  split.nodes[3].polygons = {square(1, 10, 522, 200), square(2, 300, 522, 200)};
  split.nodes[4].polygons = {square(5, 522, 522, 50), square(6, 600, 522, 50),
                             square(7, 700, 522, 50)};
  EXPECT_TRUE(says(load_error(fuzz::encode_save(split)), "polygon id 3 twice"));
  split.nodes[2].polygons[0].id = 4;
  std::istringstream in(fuzz::encode_save(split));
  EXPECT_TRUE(Landscape::load(in).check().ok());
}

// I4/I5 as the tree is read: a node with no side longer than min_cell_size is a cell.
TEST(LoadRefuses, ANodeTooSmallToSplitThatIsSplit) {
  SaveFile f;
  f.min_cell_size = 1024;  // the whole world is one cell
  f.nodes.push_back(SavedNode{true, {}});
  for (int i = 0; i < 4; ++i) f.nodes.push_back(SavedNode{});
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "a cell too small to split is split"));
}

// I9 as the tree is read: in grid mode nothing splits at or below the grid depth.
TEST(LoadRefuses, AGridNodeSplitBelowTheGridDepth) {
  SaveFile f;
  f.grid_depth = 0;  // the grid is the root cell alone
  f.nodes.push_back(SavedNode{true, {}});
  for (int i = 0; i < 4; ++i) f.nodes.push_back(SavedNode{});
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "a grid node split below the grid depth"));
  f.nodes.resize(1);
  f.nodes[0].inner = false;
  std::istringstream in(fuzz::encode_save(f));
  EXPECT_TRUE(Landscape::load(in).check().ok());
}

// A delta beyond twice the bound cannot come from two in-range points; a point beyond the bound
// is refused however it is reached.
TEST(LoadRefuses, CoordinatesBeyondTheBound) {
  SaveFile f = one_square();
  f.nodes[0].polygons[0].ring[1] = {std::numeric_limits<std::int64_t>::max() / 2, 10};
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "coordinate beyond the bound"));
  f = one_square();
  f.nodes[0].polygons[0].ring[2] = {30, 4 * kCoordBound};
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "coordinate beyond the bound"));
  f = one_square();
  f.nodes[0].polygons[0].ring[0] = {kCoordBound + 1, 10};  // a delta in range, a point not
  EXPECT_TRUE(says(load_error(fuzz::encode_save(f)), "coordinate beyond the bound"));
}

// --- the stream ---------------------------------------------------------------------------------

// A stream whose buffer fails on reading (a disk error): the stream's badbit.
class FailingBuffer : public std::streambuf {
 protected:
  int_type underflow() override { throw std::runtime_error("disk error"); }
};

TEST(LoadRefuses, AStreamThatFails) {
  FailingBuffer buffer;
  std::istream in(&buffer);
  try {
    Landscape::load(in);
    FAIL() << "loaded";
  } catch (const LoadError& e) {
    EXPECT_TRUE(says(e.what(), "the stream failed"));
    EXPECT_EQ(e.offset, 0u);
  }
}

// No more bytes are read than a world within the limits can take.
TEST(LoadRefuses, AFileLargerThanTheLimitsAllow) {
  const std::string bytes = fuzz::encode_save(one_square());
  const LandscapeLimits tiny{.max_vertices = 0, .max_cells = 0};
  EXPECT_TRUE(says(load_error(bytes, tiny), "file larger than the limits allow"));
  // Limits at the top of the range do not overflow the bound on the bytes.
  const std::size_t most = std::numeric_limits<std::size_t>::max();
  std::istringstream in(bytes);
  const Landscape l =
      Landscape::load(in, {.max_vertices = most, .max_shape_vertices = most, .max_cells = most});
  EXPECT_EQ(l.stats().polygons, 1u);
}

}  // namespace
}  // namespace edgeland::test
