// The memory a load takes (issue 27, point 1), measured by replacing the global allocation
// functions (tests/support/allocation_meter.cpp), so this is its own executable: a small multiple
// of the file plus the world it returns, and for a refused file a small multiple of the file.
// Before, the issue's full quadtree of empty cells (0.6 MB) took 117 MB before it was refused, and
// at 9.8 MB ran out of memory with std::bad_alloc instead of a LoadError.
#include <gtest/gtest.h>

#include <sstream>

#include "allocation_meter.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "save_file.hpp"

namespace edgeland::test {
namespace {

constexpr std::size_t kSlack = std::size_t{1} << 20;

// The stream is the caller's: what load itself needs is measured.
std::size_t peak_of_load(const std::string& bytes) {
  std::istringstream in(bytes);
  return fuzz::peak_heap_during([&] {
    try {
      Landscape::load(in);
    } catch (const LoadError&) {
    }
  });
}

TEST(LoadMemory, TheIssuesHostileFilesAreRefusedWithinTwiceTheirSize) {
  for (const int depth : {9, 10, 11}) {  // 0.6, 2.4 and 9.8 MB
    const std::string bytes = fuzz::encode_save(fuzz::full_tree_of_empty_cells(depth));
    const std::size_t peak = peak_of_load(bytes);
    EXPECT_LE(peak, 2 * bytes.size() + kSlack)
        << "depth " << depth << ": " << bytes.size() << " bytes";
  }
}

TEST(LoadMemory, AValidWorldTakesTheFileAndTwiceTheWorld) {
  Landscape l({{0, 0}, {4096, 4096}}, 1);
  for (int i = 0; i < 400; ++i) {
    const std::int64_t x = 97 * i % 4000, y = 61 * i % 4000;
    l.carve(PolygonSet{{{x, y}, {x + 60, y + 8}, {x + 50, y + 70}, {x + 4, y + 52}}});
  }
  std::ostringstream out;
  l.save(out);
  const std::string bytes = out.str();
  std::size_t world = 0;
  std::istringstream in(bytes);
  const std::size_t peak =
      fuzz::peak_heap_during([&] { world = Landscape::load(in).stats().bytes; });
  EXPECT_GT(world, bytes.size());
  EXPECT_LE(peak, 4 * bytes.size() + 2 * world + kSlack)
      << "file " << bytes.size() << ", world " << world;
}

// Memory that runs out during a load is a LoadError, never a std::bad_alloc.
TEST(LoadMemory, RunningOutOfMemoryIsALoadError) {
  Landscape l({{0, 0}, {4096, 4096}}, 1);
  for (int i = 0; i < 100; ++i) {
    const std::int64_t x = 97 * i % 4000, y = 61 * i % 4000;
    l.carve(PolygonSet{{{x, y}, {x + 60, y + 8}, {x + 50, y + 70}, {x + 4, y + 52}}});
  }
  std::ostringstream out;
  l.save(out);
  std::istringstream in(out.str());
  const fuzz::HeapBudget budget(fuzz::heap_in_use() + 3 * out.str().size());
  EXPECT_THROW(Landscape::load(in), LoadError);
}

}  // namespace
}  // namespace edgeland::test
