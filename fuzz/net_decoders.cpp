// The server's input as a fuzz target (issue 37, item 5): arbitrary bytes as one message from a
// client, decoded and handled as Server::receive handles it (net/request_checks.hpp: the same
// decisions), against a world with regions that the server holds whole or in part. Declared in
// decoders.hpp.
#include <exception>
#include <string>
#include <vector>

#include "allocation_meter.hpp"
#include "decoders.hpp"
#include "delta_worlds.hpp"
#include "edgeland/net/request_checks.hpp"
#include "edgeland/spatial/delta.hpp"

namespace edgeland::fuzz {

using namespace edgeland::net;  // the messages and the server's decisions

namespace {

// The server's worlds: every region held, and half of them (the other owner's as stubs, which
// edits skip: a server of item 6).
const std::vector<Landscape>& server_worlds() {
  static const std::vector<Landscape> worlds = [] {
    Landscape half = edited_world(true);
    for (const TreePath& p : half.region_paths())
      if (p.front() % 2 == 1) half.unload_region(p);
    half.set_unloaded_policy(UnloadedRegions::kSkip);
    return std::vector<Landscape>{edited_world(true), half};
  }();
  return worlds;
}

// The client's granted box and regions: the lower half of the world, or all of it.
const Box64 kLowerHalf{{0, 0}, {1024, 512}};
bool in_lower_half(const TreePath& p) { return !p.empty() && p.front() < 2; }

// A decoded message holds at most a constant times its bytes (a path per byte of a count is the
// largest: a vector of 24 bytes).
constexpr std::size_t kDecodeBytesPerByte = 64;
constexpr std::size_t kSlack = std::size_t{1} << 16;

// An EDIT: refused with a typed reason and the world unchanged, or applied in checked mode to a
// world that passes check(). Anything else thrown would take the server down.
std::optional<Finding> handle_edit(const Landscape& base, const Box64& granted, std::string delta,
                                   bool fix) {
  if (fix) fix_checksum(delta);
  Landscape world = base;
  world.set_checked(true);
  try {
    EditVerdict verdict = check_edit_request(world, granted, EditPolicy{}, delta);
    if (!verdict.accepted()) return std::nullopt;
    if (!apply_accepted(world, verdict.edits, verdict.refusal)) {
      if (world.state_hash() != base.state_hash())
        return Finding{"a refused edit changed the world", ""};
      return std::nullopt;
    }
  } catch (const std::exception& e) {
    return Finding{std::string("the server's edit handling threw: ") + e.what(), ""};
  }
  const LandscapeReport report = world.check();
  if (!report.ok())
    return Finding{"an accepted edit left check() failing: " + report.problems[0], ""};
  return std::nullopt;
}

// A PATCH answer: within what the world's nodes take (each node once), and applied to the world
// it came from it changes nothing.
std::optional<Finding> check_patch(const Landscape& world, const std::vector<TreePath>& paths) {
  Delta d;
  try {
    d = patch_delta(world, 1, paths, world.state_hash());
  } catch (const LandscapeError&) {  // a region this server does not hold (Server::patch)
    return std::nullopt;
  }
  if (encode_delta(d).size() > world.stats().bytes + 64 * paths.size() + kSlack)
    return Finding{"a PATCH answer is bigger than the world", ""};
  Landscape again = world;
  again.apply_delta(d, {.base = true, .result = true});
  if (again.state_hash() != world.state_hash())
    return Finding{"a PATCH of a world's own nodes changed it", ""};
  return std::nullopt;
}

// HASHES and PATCH_REQUEST: refused, or answered without an exception, within bounds.
std::optional<Finding> handle_repair(const Landscape& world, const std::vector<TreePath>& paths,
                                     bool patch, bool lower_half) {
  try {
    const auto may_ask = [&](const TreePath& p) { return !lower_half || in_lower_half(p); };
    if (check_repair_request(world, paths, patch, EditPolicy{}, may_ask)) return std::nullopt;
    if (patch) return check_patch(world, paths);
    Digests reply{1, {}};
    for (const TreePath& p : paths) reply.digests.push_back(world.node_digest(p));
    if (encode_message(reply).size() > 64 * paths.size() + kSlack)
      return Finding{"a DIGESTS answer is out of proportion to its request", ""};
  } catch (const std::exception& e) {
    return Finding{std::string("the server's repair handling threw: ") + e.what(), ""};
  }
  return std::nullopt;
}

std::optional<Finding> handle(const Message& m, std::uint8_t flags) {
  const Landscape& world = server_worlds()[(flags >> 1) % 2];
  const bool lower_half = (flags & 4) != 0;
  if (const auto* e = std::get_if<EditRequest>(&m))
    return handle_edit(world, lower_half ? kLowerHalf : world.world(), e->delta, flags & 1);
  if (const auto* h = std::get_if<HashesRequest>(&m))
    return handle_repair(world, h->paths, false, lower_half);
  if (const auto* p = std::get_if<PatchRequest>(&m))
    return handle_repair(world, p->paths, true, lower_half);
  return std::nullopt;  // HELLO and the server's own messages: decoded, round-tripped
}

}  // namespace

std::optional<Finding> run_net_message(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return std::nullopt;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::optional<Message> m;
  std::string other;
  const std::size_t peak = peak_heap_during([&] {
    try {
      m = decode_message(bytes);
    } catch (const ProtocolError&) {
    } catch (const std::exception& e) {
      other = e.what();
    }
  });
  if (!other.empty()) return Finding{"decode_message threw something untyped: " + other, ""};
  if (peak > kDecodeBytesPerByte * bytes.size() + kSlack)
    return Finding{"decoding a message of " + std::to_string(bytes.size()) + " bytes took " +
                       std::to_string(peak),
                   ""};
  if (!m) return std::nullopt;
  const std::string again = encode_message(*m);
  if (encode_message(decode_message(again)) != again)
    return Finding{"a decoded message does not round-trip", ""};
  return handle(*m, data[0]);
}

std::vector<std::string> net_message_seeds() {
  std::vector<std::string> seeds;
  const auto add = [&](std::uint8_t flags, const Message& m) {
    seeds.push_back(std::string(1, static_cast<char>(flags)) + encode_message(m));
  };
  const Landscape& world = server_worlds()[0];
  const auto command = [&](const Edit& e) {
    Delta d;
    d.header = {DeltaKind::kCommand, kAlgorithmVersion, world.world_hash(), 0, 0, 0};
    d.edits.push_back(e);
    return encode_delta(d);
  };
  const ValidSet low(PolygonSet{square({300, 200}, 60)}), high(PolygonSet{square({700, 800}, 60)});
  add(0, EditRequest{1, command(Edit::carve(low))});
  add(4, EditRequest{2, command(Edit::fill(low, 3))});
  add(2 | 4, EditRequest{3, command(Edit::carve(high))});  // outside the lower half
  add(2, EditRequest{4, command(Edit::relabel(high, MaterialMap().set(1, 4).set(0, 2)))});
  add(0, HashesRequest{1, {{}, {0}, {1, 2}, {3, 3, 3}}});
  add(2 | 4, HashesRequest{2, {{0, 1}, {1, 0, 2}}});
  add(0, PatchRequest{3, {{0}, {1, 2}, {3, 1}}});
  add(2, PatchRequest{4, {{0, 0}, {1}, {2, 3}}});
  add(4, PatchRequest{5, {{}}});
  add(0, Hello{});
  add(0, Checkpoint{1, world.state_hash(), {{0, 1}, {5, 2}}});
  return seeds;
}

}  // namespace edgeland::fuzz
