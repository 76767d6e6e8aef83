// `edgeland serve`: the authoritative server of a shared world (net/README.md). Prints one JSON
// line when it listens (its port) and one when it stops (what it did: edits, rejections, bytes,
// CPU time, the state hash).
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/net/server.hpp"
#include "net_options.hpp"

namespace edgeland::cli {
namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

struct ServeArgs {
  net::ServerOptions server;
  WorldArgs world;
  int seconds = 60;
  bool until_idle = false;
  StoreArgs store;
};

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

nlohmann::ordered_json summary(const net::Server& s, double wall, double cpu) {
  const net::ServerStats st = s.stats();
  nlohmann::ordered_json out;
  out["sequence"] = st.sequence;
  out["edits"] = st.edits;
  out["debris"] = st.debris;
  out["joins"] = st.joins;
  out["leaves"] = st.leaves;
  out["dropped"] = st.dropped;
  out["rejects"] = rejects_json(st.rejects);
  out["commands_sent"] = st.commands_sent;
  out["command_bytes"] = st.command_bytes;
  out["bytes_sent"] = st.bytes_sent;
  out["bytes_received"] = st.bytes_received;
  out["repair_bytes"] = st.repair_bytes;
  out["checkpoints"] = st.checkpoints;
  out["wall_seconds"] = wall;
  out["cpu_seconds"] = cpu;
  out["state_hash"] = log::state_hash_hex(s.world().state_hash());
  return out;
}

int run_serve(const ServeArgs& a) {
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  StoreSession store(a.store, a.world);
  net::ServerOptions options = a.server;
  options.first_sequence = store.sequence();
  net::Server server(store.world(), options);
  std::cout
      << nlohmann::ordered_json{{"listening", a.server.address}, {"port", server.port()}}.dump()
      << std::endl;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  const auto end = start + std::chrono::seconds(a.seconds);
  bool joined = false;
  while (!g_stop && std::chrono::steady_clock::now() < end) {
    server.step(2);
    store.after_step(server);
    const net::ServerStats st = server.stats();
    joined = joined || st.joins > 0;
    if (a.until_idle && joined && st.joins == st.leaves + st.dropped) break;
  }
  server.finish();
  store.finish(server);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << summary(server, wall, cpu_seconds() - cpu_start).dump() << std::endl;
  return kExitOk;
}

}  // namespace

Command add_serve_command(CLI::App& parent) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* app = parent.add_subcommand(
      "serve", "Run the authoritative server of a shared world over ENet (net/README.md).");
  app->add_option("--address", a->server.address, "the IP address to listen on")
      ->default_val("127.0.0.1");
  app->add_option("--port", a->server.port, "the UDP port (0: a free one, printed)");
  add_world_options(*app, a->world);
  app->add_option("--seconds", a->seconds, "stop after this many seconds")->default_val(60);
  app->add_flag("--until-idle", a->until_idle, "stop once every client that joined has left");
  net::EditPolicy& p = a->server.policy;
  app->add_option("--edits-per-second", p.edits_per_second, "a client's sustained edit rate")
      ->default_val(p.edits_per_second);
  app->add_option("--burst", p.burst, "edits a client may send at once")->default_val(p.burst);
  app->add_option("--flood-limit", p.flood_limit,
                  "rejected messages in ten seconds before a client is disconnected")
      ->default_val(p.flood_limit);
  app->add_option("--max-message", p.max_message, "bytes of one edit message")
      ->default_val(p.max_message);
  app->add_option("--max-packet", p.max_packet, "ENet's limit on any packet")
      ->default_val(p.max_packet);
  auto checkpoint_ms = std::make_shared<int>(1000);
  app->add_option("--checkpoint-ms", *checkpoint_ms, "milliseconds between checkpoints")
      ->default_val(1000)
      ->each([a](const std::string& v) {
        a->server.checkpoint_every = std::chrono::milliseconds(std::stoi(v));
      });
  app->add_option("--snapshot-every", a->server.snapshot_every,
                  "edits logged before the join snapshot is taken again")
      ->default_val(a->server.snapshot_every);
  app->add_flag("--debris", a->server.debris,
                "detach debris islands after each edit and broadcast them as commands");
  add_store_options(*app, a->store);
  app->footer(
      "Prints {\"listening\":..., \"port\":N} when it listens and a JSON summary when it "
      "stops (on --seconds, --until-idle, SIGTERM or SIGINT). Exit status 0; 2 for a bad "
      "command line or a store that cannot be opened.");
  return {app, [a] { return run_serve(*a); }};
}

}  // namespace edgeland::cli
