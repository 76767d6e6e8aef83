// Deltas (issue 37, items 1 and 3; spatial/README.md "Deltas, divergence and repair"): the
// envelope and its three kinds round-trip, lockstep by COMMAND reaches the writer's state hash,
// late join is a snapshot and the COMMANDs after it, CHANGES keep a thin client's mirror equal to
// the world, and hostile bytes are refused with a typed error and the world unchanged.
#include "edgeland/spatial/delta.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "pinned_sequence.hpp"

namespace edgeland {
namespace {

using Kind = Edit::Kind;

// A stream of edits of every kind over a 4096^2 world: blobs of radius 20-140.
Edit edit_number(std::uint64_t& seed) {
  const Point64 c{static_cast<std::int64_t>(pinned::splitmix64(seed) % 4400) - 150,
                  static_cast<std::int64_t>(pinned::splitmix64(seed) % 4400) - 150};
  const std::int64_t r = 20 + static_cast<std::int64_t>(pinned::splitmix64(seed) % 120);
  ValidSet shape(PolygonSet{pinned::blob(c, r)});
  switch (pinned::splitmix64(seed) % 6) {
    case 0:
      return Edit::fill(std::move(shape), 2);
    case 1:
      return Edit::replace(std::move(shape), 1, 3);
    case 2:
      return Edit::fill_empty(std::move(shape), 4);
    case 3:
      return Edit::relabel(std::move(shape), MaterialMap().set(1, 2).set(2, 1).set(0, 5));
    default:
      return Edit::carve(std::move(shape));
  }
}

// Two deltas are the same when their bytes are.
bool same(const Delta& a, const Delta& b) { return encode_delta(a) == encode_delta(b); }

Landscape fresh_world(Material fill = 1) { return Landscape({{0, 0}, {4096, 4096}}, fill); }

std::string save_of(const Landscape& l) {
  std::ostringstream out;
  l.save(out);
  return out.str();
}

TEST(DeltaCodec, EveryKindRoundTrips) {
  Landscape server = fresh_world();
  std::uint64_t seed = 37;
  for (std::uint64_t sequence = 1; sequence <= 40; ++sequence) {
    const Landscape before = server;
    const Edit edit = edit_number(seed);
    const ChangeSet changes = apply_edit(server, edit);
    for (const Delta& d :
         {command_delta(before, server, sequence, edit),
          changes_delta(before, server, sequence, changes),
          patch_delta(server, sequence, std::vector<TreePath>{TreePath{}}, before.state_hash())}) {
      EXPECT_TRUE(same(decode_delta(encode_delta(d)), d));
    }
  }
}

// Each kind comes back with its map and shape; a map of another form than its kind's comes back
// as a relabel with that map (what an Edit does is its map).
TEST(DeltaCodec, AnEditOfEachKindKeepsItsMapAndShape) {
  const ValidSet shape(
      PolygonSet{pinned::blob({100, 100}, 50), pinned::blob({-1000000, 2000000000}, 70)});
  const MaterialMap odd = MaterialMap().set(0, 9).set(200, 3);
  for (const Edit& e :
       {Edit::carve(shape), Edit::fill(shape, 7), Edit::fill_empty(shape, 7),
        Edit::replace(shape, 7, 255), Edit::relabel(shape, odd), Edit{Kind::kFill, shape, odd}}) {
    Delta d;
    d.header.kind = DeltaKind::kCommand;
    d.edits = {e};
    const Edit back = decode_delta(encode_delta(d)).edits.front();
    EXPECT_EQ(back.kind, e.map == odd ? Kind::kRelabel : e.kind);
    EXPECT_EQ(back.map, e.map);
    EXPECT_EQ(back.shape.polygons(), shape.polygons());
  }
}

// Every prefix of a delta, and every byte of it changed (the checksum made right again, so the
// change reaches the reader behind it), is refused with a DeltaError (or the shape's own
// InvalidInput) or read as some delta: nothing else escapes and nothing crashes (ASan in CI).
TEST(DeltaCodec, TruncatedOrChangedBytesAreRefusedWithTheirOffset) {
  Landscape server = fresh_world();
  std::uint64_t seed = 5;
  const Landscape before = server;
  const Edit edit = edit_number(seed);
  apply_edit(server, edit);
  const std::string bytes = encode_delta(command_delta(before, server, 1, edit));
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_THROW(decode_delta(std::string_view(bytes).substr(0, n)), DeltaError) << n;
  std::string corrupt = bytes;
  corrupt[20] ^= 1;
  try {
    decode_delta(corrupt);
    FAIL() << "a changed byte passed the checksum";
  } catch (const DeltaError& e) {
    EXPECT_EQ(e.offset, 8u);
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos);
  }
  const auto fix_checksum = [](std::string& b) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i + 8 < b.size(); ++i) {
      h ^= static_cast<unsigned char>(b[i]);
      h *= 0x100000001b3ull;
    }
    for (int i = 0; i < 8; ++i) b[b.size() - 8 + i] = static_cast<char>(h >> (8 * i));
  };
  for (std::size_t i = 8; i + 8 < bytes.size(); ++i)
    for (const int flip : {0x01, 0x80, 0xff}) {
      std::string b = bytes;
      b[i] = static_cast<char>(b[i] ^ flip);
      fix_checksum(b);
      try {
        decode_delta(b);
      } catch (const DeltaError&) {
      } catch (const InvalidInput&) {  // a COMMAND's shape made invalid; CoordinateOutOfRange too
      }
    }
}

TEST(DeltaCodec, ACountLargerThanTheBytesIsRefusedBeforeAnyAllocation) {
  Delta d;
  d.header.kind = DeltaKind::kChanges;
  std::string bytes = encode_delta(d);
  // The removed count (one byte, 0) becomes a 9-byte varint claiming 2^62 ids.
  const std::size_t at = bytes.size() - 8 - 2;
  bytes.replace(at, 1, "\x80\x80\x80\x80\x80\x80\x80\x80\x40", 9);
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i + 8 < bytes.size(); ++i) {
    h ^= static_cast<unsigned char>(bytes[i]);
    h *= 0x100000001b3ull;
  }
  for (int i = 0; i < 8; ++i) bytes[bytes.size() - 8 + i] = static_cast<char>(h >> (8 * i));
  try {
    decode_delta(bytes);
    FAIL();
  } catch (const DeltaError& e) {
    EXPECT_NE(std::string(e.what()).find("count larger"), std::string::npos) << e.what();
  }
}

// Lockstep: every COMMAND of a server's edits, applied by a client, gives the server's state
// hash, which the delta's result hash checks at every step.
TEST(DeltaCommand, LockstepReachesTheServersHashAtEveryEdit) {
  Landscape server = fresh_world(), client = fresh_world();
  std::uint64_t seed = 11;
  for (std::uint64_t sequence = 1; sequence <= 150; ++sequence) {
    const Landscape before = server;
    const Edit edit = edit_number(seed);
    const ChangeSet expected = apply_edit(server, edit);
    const std::string bytes = encode_delta(command_delta(before, server, sequence, edit));
    const ChangeSet got = client.apply_delta(decode_delta(bytes));
    ASSERT_EQ(client.state_hash(), server.state_hash()) << sequence;
    EXPECT_EQ(got.removed, expected.removed);
    EXPECT_EQ(got.added.size(), expected.added.size());
  }
  EXPECT_TRUE(client.check().ok());
}

// Frame batches travel as one COMMAND (the batch form): a client applying the server's batches
// runs apply_batch and reaches the server's hash at every batch; the bytes hold every edit in
// order. An empty batch is no command: applying one is refused and changes nothing.
TEST(DeltaCommand, BatchesReachTheServersHashAtEveryBatch) {
  Landscape server = fresh_world(), client = fresh_world();
  std::uint64_t seed = 23;
  for (std::uint64_t sequence = 1; sequence <= 60; ++sequence) {
    std::vector<Edit> batch;
    for (std::uint64_t k = 0; k < 1 + sequence % 4; ++k) batch.push_back(edit_number(seed));
    const Landscape before = server;
    const ChangeSet expected = server.apply_batch(batch);
    const Delta sent = decode_delta(encode_delta(command_delta(before, server, sequence, batch)));
    ASSERT_EQ(sent.edits.size(), batch.size());
    const ChangeSet got = client.apply_delta(sent);
    ASSERT_EQ(client.state_hash(), server.state_hash()) << sequence;
    EXPECT_EQ(got.removed, expected.removed);
    EXPECT_EQ(got.added.size(), expected.added.size());
  }
  EXPECT_TRUE(client.check().ok());
  const std::uint64_t hash = client.state_hash();
  EXPECT_THROW(client.apply_delta(command_delta(server, server, 61, std::span<const Edit>())),
               DeltaError);
  EXPECT_EQ(client.state_hash(), hash);
}

TEST(DeltaCommand, AnotherWorldAlgorithmBaseOrResultIsRefusedAndChangesNothing) {
  Landscape server = fresh_world(), client = fresh_world();
  std::uint64_t seed = 3;
  const Edit edit = edit_number(seed);
  const Landscape before = server;
  apply_edit(server, edit);
  const Delta good = command_delta(before, server, 1, edit);
  const std::uint64_t hash = client.state_hash();
  const auto refused = [&](Delta d, DeltaMismatch::Field field, const DeltaChecks& checks = {}) {
    try {
      client.apply_delta(d, checks);
      ADD_FAILURE() << "applied";
    } catch (const DeltaMismatch& e) {
      EXPECT_EQ(e.field, field);
    }
    EXPECT_EQ(client.state_hash(), hash);
  };
  Delta d = good;
  d.header.world ^= 1;
  refused(d, DeltaMismatch::Field::kWorld);
  d = good;
  d.header.algorithm = kAlgorithmVersion + 1;
  refused(d, DeltaMismatch::Field::kAlgorithm);
  d = good;
  d.header.base ^= 1;
  refused(d, DeltaMismatch::Field::kBase);
  d = good;
  d.header.result ^= 1;
  refused(d, DeltaMismatch::Field::kResult);
  // A client that knows it diverged applies without the checks.
  d.header.base ^= 1;
  client.apply_delta(d, {.base = false, .result = false});
  EXPECT_EQ(client.state_hash(), server.state_hash());
  // A world of another configuration is another world.
  LandscapeConfig kd;
  kd.tree = TreeKind::kKdTree;
  EXPECT_NE(Landscape({{0, 0}, {4096, 4096}}, 1, kd).world_hash(), client.world_hash());
}

// A hostile COMMAND's shape is out of range or invalid: the edit's own typed error, from the
// reader; a CHANGES delta is no landscape's.
TEST(DeltaCommand, AHostileShapeGetsTheEditsErrorAndChangesNothing) {
  Landscape client = fresh_world();
  const std::uint64_t hash = client.state_hash();
  // The shapes are written as they come: hostile bytes need not be a ValidSet's.
  const auto command_with = [&](const Polygon& ring) {
    std::string b = encode_delta(command_delta(
        client, client, 1, Edit::carve(ValidSet(PolygonSet{{{0, 0}, {9, 0}, {0, 9}}}))));
    // The shape's bytes: its count (1), the vertex count (3) and six one-byte deltas, before the
    // checksum; replaced by this ring's.
    std::string ring_bytes(1, static_cast<char>(ring.size()));
    Point64 prev{0, 0};
    for (const Point64 p : ring)
      for (std::int64_t v : {p.x - prev.x, p.y - prev.y}) {
        std::uint64_t z =
            (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
        for (; z >= 0x80; z >>= 7) ring_bytes += static_cast<char>(z | 0x80);
        ring_bytes += static_cast<char>(z);
        prev = p;
      }
    b.replace(b.size() - 8 - 7, 7, ring_bytes);
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i + 8 < b.size(); ++i)
      h = (h ^ static_cast<unsigned char>(b[i])) * 0x100000001b3ull;
    for (int i = 0; i < 8; ++i) b[b.size() - 8 + i] = static_cast<char>(h >> (8 * i));
    return b;
  };
  EXPECT_THROW(decode_delta(command_with({{0, 0}, {kCoordBound + 1, 0}, {0, 10}})),
               CoordinateOutOfRange);
  EXPECT_THROW(decode_delta(command_with({{0, 0}, {10, 10}, {10, 0}, {0, 10}})), InvalidInput);
  EXPECT_THROW(decode_delta(command_with({{0, 0}, {std::int64_t{1} << 62, 0}, {0, 10}})),
               DeltaError);
  // The helper writes what it is given: a valid ring decodes.
  EXPECT_EQ(decode_delta(command_with({{0, 0}, {10, 0}, {0, 10}})).edits.front().shape.polygons(),
            (PolygonSet{{{0, 0}, {10, 0}, {0, 10}}}));
  Delta changes = command_delta(client, client, 1, Edit::carve(ValidSet()));
  changes.header.kind = DeltaKind::kChanges;
  EXPECT_THROW(client.apply_delta(changes, {.base = true, .result = false}), DeltaError);
  EXPECT_EQ(client.state_hash(), hash);
}

// Late join (item 3): a snapshot taken at sequence k, then the COMMANDs after k, gives the
// server's state at every later step.
TEST(DeltaLateJoin, ASnapshotThenTheCommandsAfterItReachTheServersHash) {
  Landscape server = fresh_world();
  std::vector<std::string> log;  // log[i]: the delta of edit i + 1
  std::string snapshot;
  std::uint64_t seed = 21;
  constexpr std::uint64_t kSnapshotAt = 60;
  for (std::uint64_t sequence = 1; sequence <= 120; ++sequence) {
    const Landscape before = server;
    const Edit edit = edit_number(seed);
    apply_edit(server, edit);
    log.push_back(encode_delta(command_delta(before, server, sequence, edit)));
    if (sequence == kSnapshotAt) snapshot = save_of(server);
  }
  std::istringstream in(snapshot);
  Landscape joiner = Landscape::load(in);
  for (std::uint64_t sequence = kSnapshotAt + 1; sequence <= log.size(); ++sequence) {
    const Delta d = decode_delta(log[sequence - 1]);
    ASSERT_EQ(d.header.sequence, sequence);
    joiner.apply_delta(d);
  }
  EXPECT_EQ(joiner.state_hash(), server.state_hash());
}

// CHANGES: a thin client's mirror holds exactly the world's polygons after every edit, and its
// digest is the world's drawn digest.
TEST(DeltaChanges, AMirrorFollowsTheWorldPolygonForPolygon) {
  Landscape server = fresh_world(kEmpty);
  DrawMirror mirror;
  std::uint64_t seed = 8;
  for (std::uint64_t sequence = 1; sequence <= 80; ++sequence) {
    const Landscape before = server;
    const ChangeSet changes = apply_edit(server, edit_number(seed));
    mirror.apply(decode_delta(encode_delta(changes_delta(before, server, sequence, changes))));
    ASSERT_EQ(mirror.digest(), server.drawn_digest()) << sequence;
  }
  std::map<PolygonId, DrawnPolygon> world;
  server.polygons_in(server.world(), [&](const PolygonView& v) {
    world.emplace(v.id, DrawnPolygon{v.id, v.material, *v.polygon});
    return true;
  });
  EXPECT_EQ(mirror.polygons(), world);
  EXPECT_GT(world.size(), 20u);
}

TEST(DeltaChanges, AMirrorRefusesIdsItDoesNotHoldOrHoldsTwiceAndStaysAsItWas) {
  DrawMirror mirror;
  Delta d;
  d.header.kind = DeltaKind::kChanges;
  d.added = {{5, 1, {{0, 0}, {1, 0}, {0, 1}}}};
  mirror.apply(d);
  const std::uint64_t digest = mirror.digest();
  EXPECT_THROW(mirror.apply(d), DeltaError);  // 5 again
  Delta remove = d;
  remove.added.clear();
  remove.removed = {6};
  EXPECT_THROW(mirror.apply(remove), DeltaError);
  d.header.kind = DeltaKind::kCommand;
  EXPECT_THROW(mirror.apply(d), DeltaError);
  EXPECT_EQ(mirror.digest(), digest);
  EXPECT_EQ(mirror.polygons().size(), 1u);
}

}  // namespace
}  // namespace edgeland
