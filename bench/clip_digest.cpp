// edgeland_clip_digest: one difference per named input, printed as an FNV-1a digest of every
// output vertex (in output order), the output's vertex count and the peak resident set. Two
// builds of the library give the same outputs exactly when their lines agree: the check that a
// change of speed or memory left every result bit-identical (bench/README.md, "Zigzag stars at
// scale"). Usage: edgeland_clip_digest [NAME...]; no names: every input below.
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "scale_workloads.hpp"
#include "workloads.hpp"

namespace {

using edgeland::bench::Operands;

struct Input {
  const char* name;
  std::function<Operands()> make;
};

const std::vector<Input>& inputs() {
  using namespace edgeland::bench;
  static const std::vector<Input> kInputs = {
      {"zigzag_10000", [] { return zigzag_stars(10'000); }},
      {"zigzag_100000", [] { return zigzag_stars(100'000); }},
      {"zigzag_200000", [] { return zigzag_stars(200'000); }},
      {"zigzag_1000000", [] { return zigzag_stars(1'000'000); }},
      {"spiky_2000", [] { return spiky_stars(2'000); }},
      {"spiky_10000", [] { return spiky_stars(10'000); }},
      {"checkerboard_20000", [] { return checkerboard(20'000); }},
      {"comb_short_100000", [] { return combs(25'000, 100'000, 1'000); }},
      {"comb_long_100000", [] { return combs(25'000, 100'000'000, 1'000'000); }},
      {"smooth_100000", [] { return smooth_stars(100'000); }},
  };
  return kInputs;
}

std::uint64_t fnv1a(std::uint64_t h, std::int64_t v) {
  for (int k = 0; k < 8; ++k) {
    h ^= static_cast<std::uint64_t>(v >> (8 * k)) & 0xffu;
    h *= 0x100000001b3ull;
  }
  return h;
}

void run(const Input& in) {
  const Operands ops = in.make();
  const auto start = std::chrono::steady_clock::now();
  const edgeland::ClipResult r =
      edgeland::clip(edgeland::ClipOp::kDifference, ops.subject, ops.clip);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::uint64_t h = 0xcbf29ce484222325ull;
  std::size_t vertices = 0;
  for (const edgeland::Polygon& p : r.polygons) {
    h = fnv1a(h, static_cast<std::int64_t>(p.size()));
    for (const edgeland::Point64& v : p) h = fnv1a(fnv1a(h, v.x), v.y);
    vertices += p.size();
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%-20s digest %016llx  vertices %zu  %.2f s  peak %.0f MB\n", in.name,
              static_cast<unsigned long long>(h), vertices, seconds,
              static_cast<double>(usage.ru_maxrss) / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  for (const Input& in : inputs()) {
    bool wanted = argc == 1;
    for (int k = 1; k < argc; ++k) wanted = wanted || std::strcmp(argv[k], in.name) == 0;
    if (wanted) run(in);
  }
  return 0;
}
