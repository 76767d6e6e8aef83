#pragma once
// A client that mirrors the server's world (net/README.md): it joins from the server's snapshot,
// applies the COMMANDs (or, thin, the CHANGES) it receives, checks every checkpoint and repairs
// through node digests when it differs, and makes edits of its own at a steady rate, measuring
// how long each takes to come back. Single-threaded: the caller drives it with step().
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/net/edit_stream.hpp"
#include "edgeland/net/protocol.hpp"
#include "edgeland/spatial/delta.hpp"

namespace edgeland::net {

class EnetHost;

struct ClientOptions {
  std::string address = "127.0.0.1";
  std::uint16_t port = 0;
  Role role = Role::kFull;
  bool watch_all = true;
  std::vector<std::uint32_t> regions;  // watched region indices when not watch_all
  Box64 edit_box{{1, 1}, {0, 0}};      // where it edits (an inverted box: it makes no edits)
  std::uint32_t edits_per_second = 0;  // its own edits (0: none)
  std::uint64_t seed = 1;              // of its edits
  std::size_t max_packet = std::size_t{64} << 20;
};

struct ClientStats {
  std::uint64_t sequence = 0;  // the last sequence number applied
  std::uint64_t checkpoints = 0, matched = 0, mismatched = 0;
  std::uint64_t repairs = 0, repair_rounds = 0, repair_bytes = 0;
  std::uint64_t commands = 0, changes = 0;  // deltas applied
  std::uint64_t edits_sent = 0, edits_applied = 0, edits_rejected = 0;
  std::map<RejectReason, std::uint64_t> rejects;
  std::vector<std::uint32_t> latencies_us;  // of its own edits, send to applied
  std::uint64_t bytes_received = 0, bytes_sent = 0;
  bool welcomed = false, disconnected = false;
};

class EDGELAND_EXPORT Client {
 public:
  // Starts to connect; the first steps finish it and say HELLO (welcomed() once the server has
  // answered). Throws std::runtime_error for an address that is no IP address.
  explicit Client(ClientOptions options);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  // Handles what arrived within `timeout_ms`, then sends its edits that are due.
  void step(int timeout_ms);
  // Stops making edits; keeps applying what comes.
  void stop_editing() noexcept { editing_ = false; }
  // Asks the server to disconnect (after what is queued) and serves until it is done.
  void leave();

  // One edit request now; returns its number.
  std::uint32_t request(const Edit& edit);
  // A frame batch as one request (Landscape::apply_batch on the server and every client, one
  // COMMAND); refused whole if any edit is. Returns its number.
  std::uint32_t request(std::span<const Edit> batch);
  // Raw bytes as one message (hostile clients and their tests).
  void send_raw(const std::string& bytes);
  // Applies an edit to this client's world only: a divergence the next checkpoint finds.
  void diverge(const Edit& edit);

  bool welcomed() const noexcept { return stats_.welcomed; }
  std::uint32_t id() const noexcept { return id_; }
  const Box64& granted() const noexcept { return granted_; }
  const std::optional<Landscape>& world() const noexcept { return world_; }
  const DrawMirror& mirror() const noexcept { return mirror_; }
  // Whether the last checkpoint matched and no repair is under way.
  bool in_step() const noexcept { return in_step_; }
  ClientStats stats() const;

 private:
  void receive(const std::string& bytes);
  void rejected(const Reject& r);
  void welcome(const Welcome& m);
  void command(const Command& m);
  void changes(const Changes& m);
  void checkpoint(const Checkpoint& m);
  void digests(const Digests& m);
  void patched(const PatchReply& m);
  void start_repair(const std::vector<TreePath>& starts);
  void ask(const Message& m);
  void send_due_edits();
  std::uint64_t region_hash(std::uint32_t index) const;
  TreePath path_of(std::uint32_t index) const;

  ClientOptions options_;
  std::unique_ptr<EnetHost> host_;
  std::optional<Landscape> world_;
  DrawMirror mirror_;
  std::uint32_t id_ = 0;
  std::uint32_t peer_ = 0;  // the server, once connected
  Box64 granted_{{1, 1}, {0, 0}};
  bool editing_ = true, in_step_ = false;
  std::optional<DivergenceSearch> search_;
  std::uint32_t next_request_ = 1, next_edit_ = 1;
  std::optional<EditStream> stream_;  // its edits, once it knows its box
  std::chrono::steady_clock::time_point start_;
  std::uint64_t edits_due_sent_ = 0;
  std::map<std::uint32_t, std::chrono::steady_clock::time_point> pending_;
  ClientStats stats_;
};

}  // namespace edgeland::net
