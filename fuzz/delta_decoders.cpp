// The delta reader's fuzz target (issue 37, item 1): arbitrary bytes as a delta, decoded and
// applied to one of a few fixed worlds. Declared in decoders.hpp.
#include <algorithm>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "allocation_meter.hpp"
#include "decoders.hpp"
#include "delta_worlds.hpp"
#include "edgeland/spatial/delta.hpp"

namespace edgeland::fuzz {

LandscapeLimits delta_limits() {
  LandscapeLimits l;
  l.max_cells = 1 << 12;
  l.max_vertices = 1 << 16;
  l.max_shape_vertices = 1 << 12;
  return l;
}

Polygon square(Point64 c, std::int64_t r) {
  return {{c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y + r}, {c.x - r, c.y + r}};
}

Landscape edited_world(bool regions) {
  LandscapeConfig c;
  if (regions) {
    c.region_depth = 2;
    c.region_ids = true;
  }
  Landscape w({{0, 0}, {1024, 1024}}, 1, c, delta_limits());
  for (std::int64_t i = 0; i < 12; ++i) {
    w.carve(PolygonSet{square({80 * i + 40, 300 + 37 * i % 400}, 30 + i)});
    w.fill(PolygonSet{square({60 * i + 100, 700 - 23 * i}, 12 + i)}, 2 + i % 3);
  }
  return w;
}

void fix_checksum(std::string& bytes) {
  if (bytes.size() < 8) return;
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i + 8 < bytes.size(); ++i)
    h = (h ^ static_cast<unsigned char>(bytes[i])) * 0x100000001b3ull;
  for (int i = 0; i < 8; ++i) bytes[bytes.size() - 8 + i] = static_cast<char>(h >> (8 * i));
}

namespace {

// The worlds deltas are applied to: filled and edited a little, empty, with regions, and with
// regions one of which is unloaded (edits skip it: a client watching the others).
const std::vector<Landscape>& base_worlds() {
  static const std::vector<Landscape> worlds = [] {
    Landscape partial = edited_world(true);
    partial.unload_region({1, 2});
    partial.set_unloaded_policy(UnloadedRegions::kSkip);
    return std::vector<Landscape>{edited_world(false),
                                  Landscape({{0, 0}, {1024, 1024}}, kEmpty, {}, delta_limits()),
                                  edited_world(true), partial};
  }();
  return worlds;
}

// Decoding holds at most a constant times the delta (a Polygon per byte of a count is the
// largest: 24 bytes), and a PATCH's subtree as much as a loaded file (run_load's bound).
constexpr std::size_t kDecodeBytesPerByte = 64, kApplyBytesPerByte = 512;
constexpr std::size_t kSlack = std::size_t{1} << 20;

bool has_unloaded_region(const Landscape& world) {
  const std::vector<TreePath> paths = world.region_paths();
  return std::any_of(paths.begin(), paths.end(),
                     [&](const TreePath& p) { return !world.region_loaded(p); });
}

// A world with an unloaded region cannot be saved whole (save() throws RegionNotLoaded, as the
// partial world after a skipping COMMAND is): each loaded region's record is written, its region
// unloaded in a copy and the record read back there (load_region checks it against the stub's
// hash and summary), leaving the same state hash.
std::optional<Finding> check_region_records(const Landscape& world) {
  Landscape copy = world;
  for (const TreePath& path : world.region_paths()) {
    if (!world.region_loaded(path)) continue;
    std::stringstream record;
    world.save_region(path, record);
    copy.unload_region(path);
    copy.load_region(record);
  }
  if (copy.state_hash() != world.state_hash() || !copy.check().ok())
    return Finding{"a partial world after a delta, its regions saved and loaded, differs", ""};
  return std::nullopt;
}

std::optional<Finding> check_applied(const Landscape& world, const Landscape& before,
                                     bool refused) {
  if (refused) {
    if (world.state_hash() != before.state_hash())
      return Finding{"a refused delta changed the landscape", ""};
    return std::nullopt;
  }
  const LandscapeReport report = world.check();
  if (!report.ok())
    return Finding{"an applied delta left check() failing: " + report.problems.front(), ""};
  if (has_unloaded_region(world)) return check_region_records(world);
  std::stringstream saved;
  world.save(saved);
  if (Landscape::load(saved, delta_limits()).state_hash() != world.state_hash())
    return Finding{"a world after a delta saved and loaded has another state hash", ""};
  return std::nullopt;
}

std::optional<Finding> apply_to_world(const Delta& d, const Landscape& base,
                                      const DeltaChecks& checks, std::size_t size) {
  Landscape world = base;
  world.set_checked(true);
  bool refused = false;
  std::string other;
  const std::size_t peak = peak_heap_during([&] {
    try {
      world.apply_delta(d, checks);
    } catch (const LandscapeInternalError& e) {
      other = std::string("internal error: ") + e.what();
    } catch (const LandscapeError&) {  // DeltaError, DeltaMismatch, LimitExceeded, ...
      refused = true;
    } catch (const InvalidInput&) {  // the COMMAND's shape; CoordinateOutOfRange too
      refused = true;
    } catch (const std::exception& e) {
      other = e.what();
    }
  });
  if (!other.empty()) return Finding{"apply_delta threw something untyped: " + other, ""};
  if (d.header.kind == DeltaKind::kPatch &&
      peak > kApplyBytesPerByte * size + kSlack + 4 * base.stats().bytes)
    return Finding{"a PATCH of " + std::to_string(size) + " bytes took " + std::to_string(peak) +
                       " bytes to apply",
                   ""};
  return check_applied(world, base, refused);
}

std::optional<Finding> apply_to_mirror(const Delta& d) {
  DrawMirror mirror;
  try {
    mirror.apply(d);
  } catch (const DeltaError&) {
    if (mirror.digest() != 0 || !mirror.polygons().empty())
      return Finding{"a refused CHANGES delta changed the mirror", ""};
    return std::nullopt;
  }
  std::uint64_t digest = 0;
  for (const auto& [id, p] : mirror.polygons()) digest += polygon_digest(id, p.material, p.polygon);
  if (digest != mirror.digest())
    return Finding{"the mirror's digest is not the sum of its polygons", ""};
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_delta(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return std::nullopt;
  const std::uint8_t flags = data[0];
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (flags & 1) fix_checksum(bytes);
  std::optional<Delta> d;
  std::string other;
  const std::size_t peak = peak_heap_during([&] {
    try {
      d = decode_delta(bytes);
    } catch (const DeltaError&) {
    } catch (const InvalidInput&) {  // a COMMAND's shape; CoordinateOutOfRange too
    } catch (const std::exception& e) {
      other = e.what();
    }
  });
  if (!other.empty())
    return Finding{"decode_delta threw something other than DeltaError: " + other, ""};
  if (peak > kDecodeBytesPerByte * bytes.size() + kSlack)
    return Finding{
        "decoding " + std::to_string(bytes.size()) + " bytes took " + std::to_string(peak), ""};
  if (!d) return std::nullopt;
  const std::string again = encode_delta(*d);
  if (encode_delta(decode_delta(again)) != again)
    return Finding{"a decoded delta does not round-trip", ""};
  if (d->header.kind == DeltaKind::kChanges) return apply_to_mirror(*d);
  const Landscape& base = base_worlds()[(flags >> 1) % base_worlds().size()];
  const DeltaChecks checks{.base = (flags & 8) != 0, .result = (flags & 16) != 0};
  return apply_to_world(*d, base, checks, bytes.size());
}

std::vector<std::string> delta_seeds() {
  std::vector<std::string> seeds;
  const auto add = [&](std::uint8_t flags, const Delta& d) {
    seeds.push_back(std::string(1, static_cast<char>(flags)) + encode_delta(d));
  };
  const Landscape& filled = base_worlds()[0];
  Landscape after = filled;
  const ValidSet shape(PolygonSet{square({500, 500}, 90)});
  for (const Edit& e : {Edit::carve(shape), Edit::fill(shape, 3),
                        Edit::relabel(shape, MaterialMap().set(1, 4).set(0, 2))}) {
    Landscape next = filled;
    const ChangeSet changes = apply_edit(next, e);
    add(1 | 8 | 16, command_delta(filled, next, 1, e));
    add(1, changes_delta(filled, next, 1, changes));
    if (e.kind == Edit::Kind::kFill) after = next;
  }
  add(1 | 8 | 16, patch_delta(after, 1, {{}}, filled.state_hash()));
  add(1 | 16, patch_delta(after, 1, {{0}, {3}}, filled.state_hash()));
  add(1 | 2, patch_delta(filled, 1, {{1}}));
  // Worlds with regions: a region brought into the partial world, a repair below a region's node
  // (with its counter), a command.
  const Landscape& regions = base_worlds()[2];
  add(1 | 6 | 16, patch_delta(regions, 1, {{1, 2}}));
  Landscape diverged = regions;
  diverged.fill(PolygonSet{square({700, 300}, 40)}, 4);
  TreePath below{1, 2};
  if (!diverged.node_digest(below)->cell) below.push_back(0);
  add(1 | 4 | 16, patch_delta(diverged, 1, {below}));
  Landscape next = regions;
  apply_edit(next, Edit::carve(shape));
  add(1 | 4 | 8 | 16, command_delta(regions, next, 1, Edit::carve(shape)));
  return seeds;
}

}  // namespace edgeland::fuzz
