#include "region_record.hpp"

#include "edgeland/spatial/byte_codec.hpp"
#include "save_format.hpp"
#include "tree_codec.hpp"

namespace edgeland::detail {
namespace {

constexpr char kMagic[8] = {'E', 'D', 'G', 'E', 'R', 'E', 'G', 'N'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kChecksumBytes = 8;
constexpr std::size_t kMaxPath = 10;  // the deepest region (LandscapeConfig::region_depth)

void write_summary(ByteWriter& w, const RegionSummary& s) {
  w.fixed(s.world, 8);
  w.varint(s.path.size());
  for (const std::uint8_t i : s.path) w.u8(i);
  w.fixed(s.hash, 8);
  for (const std::uint64_t v :
       {std::uint64_t{s.polygons}, std::uint64_t{s.vertices}, std::uint64_t{s.cells},
        std::uint64_t{s.deepest}, s.min_id, s.max_id, s.next_id})
    w.varint(v);
  w.varint(s.twice_areas.size());
  for (const auto& [m, a] : s.twice_areas) {
    w.u8(m.value());
    w.fixed(int128_low(a), 8);
    w.fixed(int128_high(a), 8);
  }
}

RegionSummary read_summary(ByteReader& in) {
  RegionSummary s;
  s.world = in.fixed(8);
  const std::size_t length = in.count(1);
  if (length > kMaxPath) in.fail("region path deeper than any region");
  s.path.resize(length);
  for (std::uint8_t& i : s.path) {
    i = static_cast<std::uint8_t>(in.fixed(1));
    if (i > 3) in.fail("path index above 3");
  }
  s.hash = in.fixed(8);
  s.polygons = in.varint();
  s.vertices = in.varint();
  s.cells = in.varint();
  s.deepest = static_cast<std::uint32_t>(in.varint());
  s.min_id = in.varint();
  s.max_id = in.varint();
  s.next_id = in.varint();
  const std::size_t areas = in.count(17);
  int previous = 0;
  for (std::size_t k = 0; k < areas; ++k) {
    const auto m = static_cast<int>(in.fixed(1));
    if (m <= previous) in.fail("region areas not by ascending solid material");
    const std::uint64_t low = in.fixed(8), high = in.fixed(8);
    s.twice_areas.emplace_back(static_cast<std::uint8_t>(m), int128_from_words(low, high));
    previous = m;
  }
  return s;
}

std::string record(const Node* region, const RegionSummary& summary) {
  ByteWriter w;
  for (const char c : kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.fixed(kVersion, 4);
  write_summary(w, summary);
  if (region) write_tree(w, *region);
  w.fixed(save_format::fnv1a64(w.bytes()), 8);
  return std::move(w.bytes());
}

}  // namespace

std::string write_region_record(const Node& region, const RegionSummary& summary) {
  return record(&region, summary);
}

std::string write_summary_record(const RegionSummary& summary) { return record(nullptr, summary); }

RegionRecord read_region_record(std::string_view bytes) {
  ByteReader in(bytes, 0, bytes.size());
  if (bytes.size() < sizeof kMagic + 4 + kChecksumBytes) in.fail("too short for a region record");
  if (bytes.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic))
    in.fail("not a region record");
  const std::size_t end = bytes.size() - kChecksumBytes;
  ByteReader tail(bytes, end, bytes.size());
  const std::uint64_t checksum = tail.fixed(kChecksumBytes);
  in = ByteReader(bytes, sizeof kMagic, end);
  if (checksum != save_format::fnv1a64(bytes.substr(0, end)))
    in.fail("checksum mismatch: the region record is corrupt");
  if (const auto v = in.fixed(4); v != kVersion)
    in.fail("unsupported region record version " + std::to_string(v));
  RegionRecord r;
  r.summary = read_summary(in);
  r.subtree_at = in.at();
  r.subtree_end = end;
  return r;
}

}  // namespace edgeland::detail
