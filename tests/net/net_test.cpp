// The server and its clients in one process over 127.0.0.1 (issue 37, items 2, 3 and 5;
// net/README.md): lockstep by COMMAND with every checkpoint matched, repair of a client that
// diverged (and what it costs against a whole save), interest management, late join from the
// snapshot and the log, thin clients, debris as commands, and hostile messages refused while the
// others go on. Every loop is bounded by a deadline.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <sstream>

#include "edgeland/net/client.hpp"
#include "edgeland/net/request_checks.hpp"
#include "edgeland/net/server.hpp"

namespace edgeland::net {
namespace {

using Clock = std::chrono::steady_clock;

Landscape region_world(Material fill = 1) {
  LandscapeConfig c;
  c.region_depth = 3;
  c.region_ids = true;
  return Landscape({{0, 0}, {4096, 4096}}, fill, c);
}

// A world with some detail already: 400 blobs carved and filled (the repair's figure compares
// with a whole save of it).
Landscape detailed_world() {
  Landscape w = region_world();
  for (std::int64_t i = 0; i < 400; ++i) {
    const Point64 c{(i * 977) % 4000 + 40, (i * 613) % 4000 + 40};
    const ValidSet blob(PolygonSet{{{c.x - 30, c.y - 20},
                                    {c.x + 25, c.y - 30},
                                    {c.x + 35, c.y + 10},
                                    {c.x, c.y + 35},
                                    {c.x - 35, c.y + 15}}});
    apply_edit(w, i % 3 ? Edit::carve(blob) : Edit::fill(blob, 2));
  }
  return w;
}

struct Steps {
  Server& server;
  std::vector<Client*> clients;
  // Steps everyone until `done` or the deadline; false on the deadline.
  bool until(const std::function<bool()>& done, int max_ms = 20000) {
    const auto end = Clock::now() + std::chrono::milliseconds(max_ms);
    while (Clock::now() < end) {
      server.step(1);
      for (Client* c : clients) c->step(0);
      if (done()) return true;
    }
    return false;
  }
  void for_ms(int ms) {
    until([] { return false; }, ms);
  }
};

ClientOptions options(std::uint16_t port, const Box64& box = {{1, 1}, {0, 0}},
                      std::uint32_t rate = 0, std::uint64_t seed = 1) {
  ClientOptions o;
  o.port = port;
  o.edit_box = box;
  o.edits_per_second = rate;
  o.seed = seed;
  return o;
}

ServerOptions fast_checkpoints() {
  ServerOptions o;
  o.checkpoint_every = std::chrono::milliseconds(200);
  return o;
}

// All edits back and a checkpoint after them matched.
bool settled(const Client& c, std::uint64_t sequence) {
  const ClientStats s = c.stats();
  return s.edits_applied + s.edits_rejected == s.edits_sent && s.sequence == sequence &&
         c.in_step() && s.checkpoints > 0;
}

TEST(NetLockstep, ClientsMirrorTheServerAtEveryCheckpoint) {
  Server server(region_world(), fast_checkpoints());
  Client a(options(server.port(), {{0, 0}, {2000, 2000}}, 20, 1));
  Client b(options(server.port(), {{2048, 2048}, {4000, 4000}}, 20, 2));
  Client watcher(options(server.port()));
  Steps run{server, {&a, &b, &watcher}};
  ASSERT_TRUE(run.until([&] { return a.welcomed() && b.welcomed() && watcher.welcomed(); }));
  run.for_ms(2000);
  a.stop_editing();
  b.stop_editing();
  const std::uint64_t checkpoints = watcher.stats().checkpoints;
  ASSERT_TRUE(run.until([&] {
    return settled(a, server.sequence()) && settled(b, server.sequence()) &&
           settled(watcher, server.sequence()) && watcher.stats().checkpoints > checkpoints + 1;
  }));
  EXPECT_GE(server.sequence(), 60u);
  for (const Client* c : {&a, &b, &watcher}) {
    const ClientStats s = c->stats();
    EXPECT_EQ(s.mismatched, 0u);
    EXPECT_EQ(s.matched, s.checkpoints);
    EXPECT_EQ(c->world()->state_hash(), server.world().state_hash());
  }
  EXPECT_EQ(a.stats().edits_applied, a.stats().edits_sent);
  EXPECT_EQ(a.stats().latencies_us.size(), a.stats().edits_sent);
}

// A frame batch (Landscape::apply_batch) is one request and one COMMAND: the server applies it
// rounded once, its sequence moves by one, and every client reaches the server's hash. A batch
// with one edit outside the box granted is refused whole, and nothing of it is applied.
TEST(NetLockstep, AFrameBatchIsOneCommandForEveryClient) {
  Server server(region_world(), fast_checkpoints());
  Client editor(options(server.port(), {{0, 0}, {2000, 2000}}));
  Client watcher(options(server.port()));
  Steps run{server, {&editor, &watcher}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed() && watcher.welcomed(); }));
  const auto blob = [](std::int64_t x, std::int64_t y) {
    return ValidSet(PolygonSet{{{x, y}, {x + 60, y + 10}, {x + 30, y + 70}}});
  };
  const std::vector<Edit> batch{Edit::carve(blob(500, 500)), Edit::fill(blob(520, 530), 3),
                                Edit::replace(blob(490, 510), 3, 4)};
  Landscape expected = server.world();
  expected.apply_batch(batch);
  editor.request(batch);
  const std::vector<Edit> outside{Edit::carve(blob(700, 700)), Edit::carve(blob(3000, 3000))};
  editor.request(outside);
  ASSERT_TRUE(run.until(
      [&] { return settled(editor, server.sequence()) && settled(watcher, server.sequence()); }));
  EXPECT_EQ(server.sequence(), 1u);
  EXPECT_EQ(server.world().state_hash(), expected.state_hash());
  EXPECT_EQ(editor.stats().rejects.at(RejectReason::kNotPermitted), 1u);
  for (const Client* c : {&editor, &watcher})
    EXPECT_EQ(c->world()->state_hash(), server.world().state_hash());
}

// Item 2 end to end: a client's cell corrupted on purpose (an edit only it made) is found at the
// next checkpoint and repaired through digests and a PATCH; the bytes that cost are a small part
// of the whole save the client would otherwise need.
TEST(NetRepair, ADivergedClientIsRepairedForAFractionOfASave) {
  Server server(detailed_world(), fast_checkpoints());
  Client editor(options(server.port(), {{0, 0}, {4000, 4000}}, 50, 3));
  Client victim(options(server.port()));
  Steps run{server, {&editor, &victim}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed() && victim.welcomed(); }));
  run.for_ms(1500);
  victim.diverge(Edit::fill(ValidSet(PolygonSet{{{1000, 1000}, {1040, 1000}, {1020, 1030}}}), 7));
  editor.stop_editing();
  ASSERT_TRUE(run.until([&] {
    return victim.stats().repairs >= 1 && settled(victim, server.sequence()) &&
           settled(editor, server.sequence());
  }));
  EXPECT_EQ(victim.world()->state_hash(), server.world().state_hash());
  std::ostringstream save;
  server.world().save(save);
  const ClientStats s = victim.stats();
  EXPECT_GE(s.mismatched, 1u);
  EXPECT_LT(s.repair_bytes * 10, save.str().size());
  std::printf("repair: %llu rounds, %llu bytes of digests and patch; a save is %zu bytes\n",
              static_cast<unsigned long long>(s.repair_rounds),
              static_cast<unsigned long long>(s.repair_bytes), save.str().size());
}

// Interest management: a client watching two regions gets only the commands that reach them,
// holds the others as stubs, and its regions match the server's at every checkpoint.
TEST(NetInterest, AWatcherOfTwoRegionsGetsOnlyTheirCommands) {
  Server server(region_world(), fast_checkpoints());
  Client editor(options(server.port(), {{0, 0}, {4096, 4096}}, 50, 4));
  ClientOptions o = options(server.port());
  o.watch_all = false;
  o.regions = {0, 63};
  Client watcher(o);
  Steps run{server, {&editor, &watcher}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed() && watcher.welcomed(); }));
  run.for_ms(1500);
  editor.stop_editing();
  ASSERT_TRUE(run.until([&] {
    return settled(editor, server.sequence()) && watcher.in_step() &&
           watcher.stats().checkpoints > 3;
  }));
  const ClientStats s = watcher.stats();
  EXPECT_EQ(s.mismatched, 0u);
  EXPECT_GT(s.commands, 0u);
  EXPECT_LT(s.commands * 4, server.sequence());
  for (const TreePath& p : {TreePath{0, 0, 0}, TreePath{3, 3, 3}})
    EXPECT_EQ(watcher.world()->node_digest(p)->hash, server.world().node_digest(p)->hash);
  EXPECT_FALSE(watcher.world()->region_loaded({1, 0, 0}));
}

// Item 3: a client joining late gets the snapshot and the COMMANDs after it.
TEST(NetLateJoin, ALateClientStartsFromTheSnapshotAndTheLogAfterIt) {
  ServerOptions o = fast_checkpoints();
  o.snapshot_every = 64;
  o.policy.edits_per_second = 200;
  Server server(region_world(), o);
  Client editor(options(server.port(), {{0, 0}, {4096, 4096}}, 100, 5));
  Steps run{server, {&editor}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed(); }));
  run.for_ms(1500);
  editor.stop_editing();
  // A few more, so that the log after the last snapshot is not empty.
  EditStream more(99, {{0, 0}, {4096, 4096}});
  while (server.sequence() % 64 < 5) {
    editor.request(more.next());
    ASSERT_TRUE(run.until([&] { return settled(editor, server.sequence()); }));
  }
  ASSERT_GT(server.sequence(), 100u);
  Client late(options(server.port()));
  run.clients.push_back(&late);
  ASSERT_TRUE(run.until([&] {
    return late.welcomed() && settled(late, server.sequence()) && late.stats().checkpoints > 2;
  }));
  EXPECT_EQ(late.stats().mismatched, 0u);
  EXPECT_EQ(late.stats().commands, server.sequence() % 64);  // the log after the snapshot
  EXPECT_EQ(late.world()->state_hash(), server.world().state_hash());
}

TEST(NetThin, AThinClientDrawsExactlyTheServersPolygons) {
  Server server(region_world(kEmpty), fast_checkpoints());
  Client editor(options(server.port(), {{0, 0}, {4096, 4096}}, 50, 6));
  ClientOptions o = options(server.port());
  o.role = Role::kThin;
  Client thin(o);
  Steps run{server, {&editor, &thin}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed() && thin.welcomed(); }));
  run.for_ms(1500);
  editor.stop_editing();
  ASSERT_TRUE(run.until([&] {
    return settled(editor, server.sequence()) && thin.in_step() && thin.stats().checkpoints > 3;
  }));
  EXPECT_EQ(thin.stats().mismatched, 0u);
  EXPECT_GT(thin.stats().changes, 0u);
  EXPECT_EQ(thin.mirror().digest(), server.world().drawn_digest());
  EXPECT_EQ(thin.mirror().polygons().size(), server.world().stats().polygons);
}

// Debris travels as a command: in an empty world every fill is an island the server detaches;
// the clients apply the same carves and stay in step.
TEST(NetDebris, DetachedIslandsReachTheClientsAsCommands) {
  ServerOptions o = fast_checkpoints();
  o.debris = true;
  Server server(region_world(kEmpty), o);
  Client editor(options(server.port(), {{0, 0}, {4096, 4096}}, 50, 7));
  Steps run{server, {&editor}};
  ASSERT_TRUE(run.until([&] { return editor.welcomed(); }));
  run.for_ms(1000);
  editor.stop_editing();
  ASSERT_TRUE(run.until([&] { return settled(editor, server.sequence()); }));
  EXPECT_GT(server.stats().debris, 0u);
  EXPECT_EQ(editor.stats().mismatched, 0u);
  EXPECT_EQ(editor.world()->state_hash(), server.world().state_hash());
}

// Hostile messages get their typed rejections; the honest client loses nothing.
TEST(NetHostile, BadMessagesAreRejectedAndTheOthersGoOn) {
  ServerOptions o = fast_checkpoints();
  o.policy.flood_limit = 1000;
  Server server(region_world(), o);
  Client honest(options(server.port(), {{0, 0}, {2000, 2000}}, 20, 8));
  Client hostile(options(server.port(), {{2048, 2048}, {4000, 4000}}));
  Steps run{server, {&honest, &hostile}};
  ASSERT_TRUE(run.until([&] { return honest.welcomed() && hostile.welcomed(); }));
  hostile.send_raw(std::string("\x02\x01", 2));                                // a truncated EDIT
  hostile.send_raw(encode_message(EditRequest{1, std::string(100000, 'x')}));  // too large
  hostile.send_raw(encode_message(Hello{}));                                   // a second HELLO
  hostile.request(Edit::carve(ValidSet(PolygonSet{{{10, 10}, {50, 10}, {30, 40}}})));  // outside
  run.for_ms(1500);
  honest.stop_editing();
  ASSERT_TRUE(run.until([&] { return settled(honest, server.sequence()); }));
  const ClientStats h = hostile.stats();
  EXPECT_EQ(h.rejects.at(RejectReason::kMalformed), 2u);
  EXPECT_EQ(h.rejects.at(RejectReason::kTooLarge), 1u);
  EXPECT_EQ(h.rejects.at(RejectReason::kNotPermitted), 1u);
  EXPECT_EQ(honest.stats().edits_applied, honest.stats().edits_sent);
  EXPECT_EQ(honest.stats().mismatched, 0u);
}

// Repair requests abused: a PATCH_REQUEST naming the root 5,000 times (a reply of 5,000 whole
// worlds were it answered), the root twice, a node inside another, a path to no node, and a
// flood of HASHES past the repair rate. Each gets its typed rejection, no reply grows past a
// save of the world, and the honest client's repair and edits go on.
TEST(NetHostile, RepairRequestsThatWouldAmplifyOrFloodAreRefused) {
  ServerOptions o = fast_checkpoints();
  o.policy.flood_limit = 1000;
  Server server(detailed_world(), o);
  Client honest(options(server.port(), {{0, 0}, {2000, 2000}}, 20, 8));
  Client hostile(options(server.port()));
  Steps run{server, {&honest, &hostile}};
  ASSERT_TRUE(run.until([&] { return honest.welcomed() && hostile.welcomed(); }));
  hostile.send_raw(encode_message(PatchRequest{1, std::vector<TreePath>(5000, TreePath{})}));
  hostile.send_raw(encode_message(PatchRequest{2, {{}, {}}}));
  hostile.send_raw(encode_message(PatchRequest{3, {{1}, {1, 2}}}));
  hostile.send_raw(encode_message(PatchRequest{4, {{1, 2, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0}}}));
  run.for_ms(300);
  for (int i = 0; i < 100; ++i) hostile.send_raw(encode_message(HashesRequest{5, {{}}}));
  honest.diverge(Edit::carve(ValidSet(PolygonSet{{{100, 100}, {300, 100}, {200, 300}}})));
  run.for_ms(1500);
  honest.stop_editing();
  ASSERT_TRUE(run.until([&] { return settled(honest, server.sequence()); }));
  const ClientStats h = hostile.stats();
  EXPECT_EQ(h.rejects.at(RejectReason::kTooLarge), 1u);
  EXPECT_EQ(h.rejects.at(RejectReason::kMalformed), 3u);
  EXPECT_GE(h.rejects.at(RejectReason::kRate), 100u - o.policy.repair_burst);
  std::ostringstream save;
  server.world().save(save);
  EXPECT_LT(server.stats().repair_bytes, save.str().size());  // 5,000 roots: 5,000 saves
  EXPECT_GE(honest.stats().repairs, 1u);
  EXPECT_EQ(honest.world()->state_hash(), server.world().state_hash());
  EXPECT_EQ(honest.stats().edits_applied, honest.stats().edits_sent);
}

TEST(NetPolicy, ARepairRequestIsBoundedAndItsPatchPathsApart) {
  const Landscape w = detailed_world();
  const EditPolicy p;
  const auto all = [](const TreePath&) { return true; };
  const auto check = [&](std::vector<TreePath> paths, bool patch) {
    return check_repair_request(w, paths, patch, p, all);
  };
  EXPECT_FALSE(check({{}, {0, 1}}, false));  // digests of nested nodes are fine
  EXPECT_FALSE(check({{0}, {1, 2}, {1, 3}}, true));
  EXPECT_EQ(check({{1, 2}, {0}, {1, 2, 0}}, true)->reason, RejectReason::kMalformed);
  EXPECT_EQ(check({{3}, {3}}, true)->reason, RejectReason::kMalformed);
  EXPECT_EQ(check({{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}}, true)->reason,
            RejectReason::kMalformed);
  EXPECT_EQ(check(std::vector<TreePath>(p.max_repair_paths + 1, {0}), false)->reason,
            RejectReason::kTooLarge);
  const auto none = [](const TreePath&) { return false; };
  EXPECT_EQ(check_repair_request(w, std::vector<TreePath>{{0}}, false, p, none)->reason,
            RejectReason::kNotPermitted);
}

// A message over ENet's packet limit never reaches the server's code: ENet refuses its fragments,
// and the sender's connection times out.
TEST(NetHostile, AMessageOverTheENetLimitNeverReachesTheServer) {
  ServerOptions o = fast_checkpoints();
  o.policy.max_packet = 1 << 20;
  Server server(region_world(), o);
  Client hostile(options(server.port()));
  Steps run{server, {&hostile}};
  ASSERT_TRUE(run.until([&] { return hostile.welcomed(); }));
  hostile.send_raw(encode_message(EditRequest{1, std::string(2 << 20, 'x')}));
  ASSERT_TRUE(run.until([&] { return hostile.stats().disconnected; }));
  EXPECT_EQ(server.stats().edits, 0u);
  EXPECT_TRUE(server.stats().rejects.empty());
}

TEST(NetProtocol, EveryMessageRoundTripsAndEveryPrefixIsRefused) {
  NodeDigest d;
  d.hash = 42;
  d.children = {1, 2, 3, 4};
  const std::vector<Message> messages = {
      Hello{kProtocolVersion, Role::kThin, false, {3, 9}, {{0, 0}, {10, 10}}},
      EditRequest{7, "delta"},
      HashesRequest{1, {{}, {0, 3}}},
      PatchRequest{2, {{1}}},
      Welcome{
          5, {{0, 0}, {64, 64}}, LandscapeConfig{}, 9, 10, {{0, 0}, {5, 5}}, {{true, "r"}}, "c"},
      Command{1, 2, "x"},
      Changes{"y"},
      Checkpoint{3, 4, {{0, 5}}},
      Reject{6, RejectReason::kRate, "slow down"},
      Digests{8, {d, std::nullopt}},
      PatchReply{9, "p"}};
  for (const Message& m : messages) {
    const std::string bytes = encode_message(m);
    EXPECT_EQ(encode_message(decode_message(bytes)), bytes);
    for (std::size_t n = 0; n < bytes.size(); ++n)
      EXPECT_THROW(decode_message(std::string_view(bytes).substr(0, n)), ProtocolError);
    EXPECT_THROW(decode_message(bytes + "z"), ProtocolError);
  }
  EXPECT_THROW(decode_message(std::string("\x63", 1)), ProtocolError);
  // A count claiming more than the bytes.
  EXPECT_THROW(decode_message(std::string("\x03\x01\x00\x00\x00\xff\xff\xff\x7f", 9)),
               ProtocolError);
}

TEST(NetPolicy, TheRateAndTheFloodLimitCountInMilliseconds) {
  const Clock::time_point t0{};
  RateLimiter rate(10, 3, t0);
  EXPECT_TRUE(rate.take(t0));
  EXPECT_TRUE(rate.take(t0));
  EXPECT_TRUE(rate.take(t0));
  EXPECT_FALSE(rate.take(t0));
  EXPECT_FALSE(rate.take(t0 + std::chrono::milliseconds(99)));
  EXPECT_TRUE(rate.take(t0 + std::chrono::milliseconds(100)));
  FloodCounter flood(2);
  EXPECT_FALSE(flood.add(t0));
  EXPECT_FALSE(flood.add(t0));
  EXPECT_TRUE(flood.add(t0));
  FloodCounter later(2);
  later.add(t0);
  later.add(t0);
  EXPECT_FALSE(later.add(t0 + std::chrono::seconds(11)));
  EXPECT_TRUE(permitted({{0, 0}, {10, 10}}, {{0, 0}, {10, 10}}));
  EXPECT_FALSE(permitted({{0, 0}, {10, 10}}, {{0, 0}, {11, 10}}));
}

}  // namespace
}  // namespace edgeland::net
