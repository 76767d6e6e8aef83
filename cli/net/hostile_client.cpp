// A hostile client (hostile_client.hpp). Its COMMAND bytes are written here field by field, not by
// the library's encoder, which only writes valid shapes: a hostile peer writes anything.
#include "hostile_client.hpp"

#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/delta.hpp"
#include "net_options.hpp"

namespace edgeland::cli {
namespace {

using Clock = std::chrono::steady_clock;
using net::RejectReason;

// A COMMAND carving `shape`, whatever it is (delta.hpp's envelope, spatial/README.md).
std::string raw_command(std::uint64_t world, const PolygonSet& shape) {
  ByteWriter w;
  w.raw("EDGEDLTA");
  w.fixed(1, 4);                  // format version
  w.u8(1);                        // COMMAND
  w.fixed(kAlgorithmVersion, 4);  // algorithm
  for (const std::uint64_t v : {world, std::uint64_t{0}, std::uint64_t{0}, std::uint64_t{0}})
    w.fixed(v, 8);
  w.u8(0);      // one edit
  w.varint(1);  // count
  w.u8(0);      // carve
  w.varint(shape.size());
  for (const Polygon& ring : shape) {
    w.varint(ring.size());
    Point64 prev{0, 0};
    for (const Point64 p : ring) {
      w.zigzag(p.x - prev.x);
      w.zigzag(p.y - prev.y);
      prev = p;
    }
  }
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : w.bytes()) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  w.fixed(h, 8);
  return std::move(w.bytes());
}

std::string edit_message(std::uint32_t number, const std::string& delta) {
  return net::encode_message(net::EditRequest{number, delta});
}

struct Attack {
  std::string name;
  RejectReason expected;
  std::vector<std::string> messages;
};

std::vector<std::string> garbage() {
  std::vector<std::string> out;
  edgeland::SplitMix64 random(37);
  for (int i = 0; i < 20; ++i) {
    std::string m(1 + random.below(200), '\0');
    for (char& c : m) c = static_cast<char>(random.next());
    m[0] = static_cast<char>(i % 2 ? 2 : random.below(32));  // half claim to be edits
    out.push_back(std::move(m));
  }
  return out;
}

Polygon inside(const Box64& b, std::int64_t r) {
  return circle({b.min.x + (b.max.x - b.min.x) / 2, b.min.y + (b.max.y - b.min.y) / 2}, r);
}

std::vector<Attack> attacks(const net::Client& c, const std::string& mode) {
  const std::uint64_t world = c.world() ? c.world()->world_hash() : 0;
  const Box64& box = c.granted();
  std::vector<Attack> all = {
      {"garbage", RejectReason::kMalformed, garbage()},
      {"oversized", RejectReason::kTooLarge, {edit_message(1, std::string(128 * 1024, 'x'))}},
      {"out-of-range",
       RejectReason::kOutOfRange,
       {edit_message(2, raw_command(world, {{{0, 0}, {kCoordBound + 5, 0}, {0, 10}}}))}},
      {"invalid",
       RejectReason::kInvalidShape,
       {edit_message(3, raw_command(world, {{{box.min.x, box.min.y},
                                             {box.min.x + 10, box.min.y + 10},
                                             {box.min.x + 10, box.min.y},
                                             {box.min.x, box.min.y + 10}}}))}},
      {"outside",
       RejectReason::kNotPermitted,
       {edit_message(4, raw_command(world, {circle({box.max.x + 100, box.max.y + 100}, 20)}))}},
  };
  std::vector<std::string> flood;
  for (std::uint32_t i = 0; i < 2000; ++i)
    flood.push_back(edit_message(100 + i, raw_command(world, {inside(box, 5 + i % 7)})));
  all.push_back({"flood", RejectReason::kRate, std::move(flood)});
  if (mode == "all") return all;
  for (Attack& a : all)
    if (a.name == mode) return {std::move(a)};
  throw std::invalid_argument("unknown hostile mode '" + mode + "'");
}

}  // namespace

int run_hostile(net::Client& client, const std::string& mode, int seconds) {
  nlohmann::ordered_json verdicts = nlohmann::ordered_json::object();
  bool all_met = true;
  for (const Attack& a : attacks(client, mode)) {
    const std::uint64_t before = client.stats().rejects[a.expected];
    for (const std::string& m : a.messages) client.send_raw(m);
    const auto deadline = Clock::now() + std::chrono::seconds(seconds);
    while (Clock::now() < deadline && !client.stats().disconnected &&
           client.stats().rejects[a.expected] == before)
      client.step(5);
    const bool met = client.stats().rejects[a.expected] > before || client.stats().disconnected;
    verdicts[a.name] = met ? net::reason_name(a.expected) : "no answer";
    all_met = all_met && met;
  }
  // Whatever else comes (more rejections, a disconnect for flooding) within a second.
  for (int i = 0; i < 200 && !client.stats().disconnected; ++i) client.step(5);
  const net::ClientStats s = client.stats();
  nlohmann::ordered_json out;
  out["hostile"] = mode;
  out["verdicts"] = verdicts;
  out["rejects"] = rejects_json(s.rejects);
  out["disconnected"] = s.disconnected;
  std::cout << out.dump() << std::endl;
  return all_met ? 0 : 1;
}

Edit divergence(const net::Client& client) {
  const Box64& b = client.granted();
  const bool has_box = b.max.x - b.min.x >= 100 && b.max.y - b.min.y >= 100;
  const Box64 where = has_box ? b : client.world()->world();
  return Edit::carve(ValidSet(PolygonSet{inside(where, 30)}));
}

}  // namespace edgeland::cli
