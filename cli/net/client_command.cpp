// `edgeland client --headless`: a client that mirrors the server's world without drawing it
// (net/README.md). It edits inside the box it asks for, checks every checkpoint, repairs when it
// differs, and prints one JSON line when it stops: checkpoints matched, repairs, its edits and
// their latency, bytes. `--hostile MODE` sends what a hostile client sends instead and reports the
// rejections it got (hostile_client.hpp).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/net/client.hpp"
#include "hostile_client.hpp"
#include "net_options.hpp"

namespace edgeland::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct ClientArgs {
  bool headless = false;
  std::string server = "127.0.0.1:0";
  bool thin = false;
  std::string watch = "all";
  std::vector<std::int64_t> edit_box;
  std::uint32_t rate = 0;
  int seconds = 10, linger = 10;
  std::uint64_t seed = 1;
  std::string hostile;
  bool diverge = false;
  bool latencies = false;
};

net::ClientOptions options_of(const ClientArgs& a) {
  net::ClientOptions o;
  const std::size_t colon = a.server.rfind(':');
  o.address = a.server.substr(0, colon);
  o.port = static_cast<std::uint16_t>(std::stoul(a.server.substr(colon + 1)));
  o.role = a.thin ? net::Role::kThin : net::Role::kFull;
  o.watch_all = a.watch == "all";
  if (!o.watch_all && !a.watch.empty() && a.watch != "none") o.regions = region_list(a.watch);
  if (a.edit_box.size() == 4)
    o.edit_box = {{a.edit_box[0], a.edit_box[1]}, {a.edit_box[2], a.edit_box[3]}};
  o.edits_per_second = a.rate;
  o.seed = a.seed;
  return o;
}

nlohmann::ordered_json latency_json(std::vector<std::uint32_t> us) {
  nlohmann::ordered_json out;
  out["count"] = us.size();
  if (us.empty()) return out;
  std::sort(us.begin(), us.end());
  out["p50_us"] = us[us.size() / 2];
  out["p99_us"] = us[std::min(us.size() - 1, us.size() * 99 / 100)];
  out["max_us"] = us.back();
  return out;
}

nlohmann::ordered_json summary(const net::Client& c, bool latencies) {
  const net::ClientStats s = c.stats();
  nlohmann::ordered_json out;
  out["client"] = c.id();
  out["welcomed"] = s.welcomed;
  out["sequence"] = s.sequence;
  out["checkpoints"] = s.checkpoints;
  out["matched"] = s.matched;
  out["mismatched"] = s.mismatched;
  out["repairs"] = s.repairs;
  out["repair_rounds"] = s.repair_rounds;
  out["repair_bytes"] = s.repair_bytes;
  out["in_step"] = c.in_step();
  out["commands"] = s.commands;
  out["changes"] = s.changes;
  out["edits_sent"] = s.edits_sent;
  out["edits_applied"] = s.edits_applied;
  out["edits_rejected"] = s.edits_rejected;
  out["rejects"] = rejects_json(s.rejects);
  out["latency"] = latency_json(s.latencies_us);
  if (latencies) out["latencies_us"] = s.latencies_us;
  out["bytes_received"] = s.bytes_received;
  out["bytes_sent"] = s.bytes_sent;
  out["disconnected"] = s.disconnected;
  if (c.world() && c.world()->config().region_depth >= 0)
    out["state_hash"] = log::state_hash_hex(c.world()->state_hash());
  return out;
}

// Steps until the deadline or `done`.
template <class Done>
void serve_until(net::Client& c, Clock::time_point deadline, Done&& done) {
  while (Clock::now() < deadline && !done()) c.step(5);
}

int run_client(const ClientArgs& a) {
  net::Client client(options_of(a));
  const auto start = Clock::now();
  serve_until(client, start + std::chrono::seconds(a.seconds), [&] { return client.welcomed(); });
  if (!client.welcomed()) {
    std::cerr << "edgeland client: no WELCOME from " << a.server << '\n';
    return kExitUnreadable;
  }
  if (!a.hostile.empty()) return run_hostile(client, a.hostile, a.seconds);
  if (a.diverge) client.diverge(divergence(client));
  serve_until(client, start + std::chrono::seconds(a.seconds),
              [&] { return client.stats().disconnected; });
  client.stop_editing();
  // Until every edit came back and a later checkpoint found the world in step.
  const std::uint64_t seen = client.stats().checkpoints;
  serve_until(client, Clock::now() + std::chrono::seconds(a.linger), [&] {
    const net::ClientStats s = client.stats();
    return s.disconnected || (s.edits_applied + s.edits_rejected == s.edits_sent &&
                              s.checkpoints > seen + 1 && client.in_step());
  });
  const nlohmann::ordered_json out = summary(client, a.latencies);
  client.leave();
  std::cout << out.dump() << std::endl;
  return client.in_step() ? kExitOk : kExitInvalid;
}

}  // namespace

Command add_client_command(CLI::App& parent) {
  auto a = std::make_shared<ClientArgs>();
  CLI::App* app = parent.add_subcommand(
      "client", "Mirror the world of an `edgeland serve` server (net/README.md).");
  app->add_flag("--headless", a->headless, "no window (the only mode today)")->required();
  app->add_option("--server", a->server, "ADDRESS:PORT of the server")->required();
  app->add_flag("--thin", a->thin, "keep only the polygons (CHANGES deltas), no landscape");
  app->add_option("--watch", a->watch, "the regions watched: all, none, or indices 0,5,...")
      ->default_val("all");
  app->add_option("--edit-box", a->edit_box, "X0 Y0 X1 Y1: where this client edits")->expected(4);
  app->add_option("--edits-per-second", a->rate, "its own edits (0: none)")->default_val(0);
  app->add_option("--seconds", a->seconds, "how long it edits")->default_val(10);
  app->add_option("--linger", a->linger,
                  "at most this long after, until its edits came back and a checkpoint matched")
      ->default_val(10);
  app->add_option("--seed", a->seed, "of its edits")->default_val(1);
  app->add_option("--hostile", a->hostile,
                  "garbage, oversized, out-of-range, invalid, outside, flood or all: send that "
                  "instead of edits and report the rejections");
  app->add_flag("--print-latencies", a->latencies, "every edit's latency in the JSON line");
  app->add_flag("--diverge", a->diverge,
                "apply one edit to its own world only, so the next checkpoint differs and it "
                "repairs");
  app->footer(
      "Prints one JSON line when it stops. Exit status 0 when its world is in step with "
      "the server's at the end (hostile: when every attack got its rejection or a "
      "disconnect), 1 otherwise, 2 when the server does not answer.");
  return {app, [a] { return run_client(*a); }};
}

}  // namespace edgeland::cli
