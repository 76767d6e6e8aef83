#pragma once
// The authoritative server (net/README.md): one world, edits validated and applied in the order
// they arrive, broadcast as COMMAND deltas to the clients watching the regions they reach (CHANGES
// to thin clients), checkpoints every second, late join from a snapshot and the log after it,
// repair answers. Single-threaded: the caller drives it with step().
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/net/edit_policy.hpp"
#include "edgeland/net/protocol.hpp"
#include "edgeland/net/request_checks.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::net {

class EnetHost;
class ServerDebris;

struct ServerOptions {
  std::string address = "127.0.0.1";
  std::uint16_t port = 0;  // 0: a free port (Server::port says which)
  std::size_t max_clients = 64;
  EditPolicy policy;
  std::chrono::milliseconds checkpoint_every{1000};
  std::size_t snapshot_every = 256;  // edits logged before the snapshot is taken again
  bool debris = false;               // detach islands after each edit, broadcast as commands
  std::uint64_t first_sequence = 0;  // the sequence number the world is at (a store's)
};

struct ServerStats {
  std::uint64_t sequence = 0, edits = 0, debris = 0, checkpoints = 0, joins = 0, leaves = 0;
  std::uint64_t dropped = 0;                           // clients disconnected for flooding
  std::map<RejectReason, std::uint64_t> rejects;       // by reason
  std::uint64_t command_bytes = 0, commands_sent = 0;  // COMMAND messages sent, their bytes
  std::uint64_t bytes_sent = 0, bytes_received = 0;    // ENet's totals (protocol included)
  std::uint64_t repair_bytes = 0;                      // DIGESTS and PATCH messages sent
};

class EDGELAND_EXPORT Server {
 public:
  // `world` must have regions (LandscapeConfig::region_depth >= 0). Throws std::runtime_error
  // when it cannot listen, std::invalid_argument for a world without regions.
  Server(Landscape world, ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  std::uint16_t port() const;
  // Serves events for up to `timeout_ms`, then sends a checkpoint when one is due.
  void step(int timeout_ms);
  // A last checkpoint to every client, then every client asked to disconnect.
  void finish();

  const Landscape& world() const noexcept { return world_; }
  std::uint64_t sequence() const noexcept { return sequence_; }
  ServerStats stats() const;

 private:
  struct Client;
  struct Logged {
    std::uint64_t sequence;
    std::vector<std::uint32_t> regions;  // region indices the edit reached
    std::string message;                 // the COMMAND message as sent
  };
  struct Snapshot {
    std::uint64_t sequence = 0;
    std::vector<std::string> records, summaries;  // per region, tree order
    std::vector<std::uint64_t> hashes;
  };

  void receive(std::uint32_t peer, const std::string& bytes);
  void hello(Client& c, const Hello& m);
  void edit(Client& c, const EditRequest& m);
  void hashes(Client& c, const HashesRequest& m);
  void patch(Client& c, const PatchRequest& m);
  std::optional<Refusal> repair_refusal(Client& c, const std::vector<TreePath>& paths, bool patch);
  void reject(Client& c, std::uint32_t number, RejectReason reason, const std::string& message);
  void apply_and_broadcast(Client& c, std::uint32_t number, EditVerdict& verdict);
  void broadcast(std::uint32_t origin, std::uint32_t number, const Landscape& before,
                 std::span<const Edit> edits, const ChangeSet& changes);
  void send_changes(Client& c, const Landscape& before, const ChangeSet& changes);
  void detach_debris(const ChangeSet& changes);
  void welcome_full(Client& c, Welcome& w);
  void welcome_thin(Client& c, Welcome& w);
  void refresh_snapshot();
  void checkpoint();
  Checkpoint checkpoint_for(const Client& c);
  std::vector<std::uint32_t> regions_of_box(const Box64& box) const;
  bool may_patch(const Client& c, const TreePath& path) const;
  void send(Client& c, const Message& m);

  Landscape world_;
  ServerOptions options_;
  std::unique_ptr<EnetHost> host_;
  std::map<std::uint32_t, std::unique_ptr<Client>> clients_;
  std::vector<TreePath> regions_;  // every region's path, by index order of regions_ (tree order)
  std::map<std::uint32_t, std::size_t> region_slot_;  // region index -> position in regions_
  std::uint64_t sequence_ = 0;
  std::vector<Logged> log_;
  Snapshot snapshot_;
  std::unique_ptr<ServerDebris> debris_;
  std::chrono::steady_clock::time_point next_checkpoint_;
  ServerStats stats_;
  std::uint32_t next_client_ = 1;
};

}  // namespace edgeland::net
