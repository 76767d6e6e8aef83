// The mirror script (README.md) in C++: writes the state hash of every frame to the file given,
// for the other languages' runs to compare with, and checks the mirror, the typed errors of bad
// input and two pinned values (the final hash and a digest of all 5000), which the native and the
// portable Int128 build must both reach. Exit 0 and "mirror: 5000 frames" when all holds.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "edgeland/kernel/errors.hpp"
#include "mirror_script.hpp"

namespace {

using namespace edgeland;
using namespace edgeland::mirror;

// Pinned from the first native run (gcc 12, -O2), reached again by the portable build.
constexpr std::uint64_t kFinalHash = 0x76a2861e8da15363;
constexpr std::uint64_t kDigest = 0x454fb2cad96a6a4e;

int failures = 0;

void expect(bool ok, int frame, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "frame %d: %s\n", frame, what);
  ++failures;
}

// The two bad edits of the script: typed errors, the world unchanged.
void bad_input(Landscape& world, int frame) {
  const std::uint64_t before = world.state_hash();
  try {
    world.fill(PolygonSet{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}, 2);
    expect(false, frame, "a bow tie was accepted");
  } catch (const InvalidInput& e) {
    expect(e.violation.rule == Rule::kSelfIntersection, frame, "the bow tie's rule");
  }
  try {
    const int material = 300;
    world.fill(PolygonSet{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, material);
    expect(false, frame, "material 300 was accepted");
  } catch (const InvalidMaterial& e) {
    expect(e.number == 300, frame, "InvalidMaterial's number");
  }
  expect(world.state_hash() == before, frame, "a refused edit changed the world");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: mirror_cpp HASHES_OUT\n");
    return 2;
  }
  std::ofstream hashes(argv[1]);
  Random random;
  Landscape world({{0, 0}, {2048, 1024}}, 1);
  Mirror mirror = polygons_of(world);
  Landscape snapshot = world;
  Mirror mirror_snapshot = mirror;
  std::uint64_t digest = 0;
  for (int f = 0; f < kFrames; ++f) {
    if (f % 1000 == 500) bad_input(world, f);
    const std::int64_t edits = 1 + random.below(3);
    for (std::int64_t e = 0; e < edits; ++e) apply_changes(mirror, draw_edit(random, world));
    if (f % 100 == 90) {
      snapshot = world;
      mirror_snapshot = mirror;
    }
    if (f % 100 == 99) {
      world = snapshot;
      mirror = mirror_snapshot;
    }
    if (f % 500 == 499) {
      std::stringstream bytes;
      world.save(bytes);
      world = Landscape::load(bytes);
    }
    const std::uint64_t h = world.state_hash();
    hashes << f << ' ' << h << '\n';
    digest = (digest ^ h) * 0x100000001B3ULL;
    if (f % 100 == 99 || f == kFrames - 1)
      expect(mirror == polygons_of(world), f, "mirror differs");
  }
  std::printf("final hash %016llx digest %016llx, %zu polygons\n",
              static_cast<unsigned long long>(world.state_hash()),
              static_cast<unsigned long long>(digest), mirror.size());
  expect(world.state_hash() == kFinalHash, kFrames, "final hash differs from the pinned one");
  expect(digest == kDigest, kFrames, "digest differs from the pinned one");
  if (failures != 0) return 1;
  std::printf("mirror: %d frames\n", kFrames);
  return 0;
}
