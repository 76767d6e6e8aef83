// The authoritative server (server.hpp; net/README.md).
#include "edgeland/net/server.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

#include "edgeland/net/request_checks.hpp"
#include "edgeland/spatial/delta.hpp"
#include "enet_host.hpp"
#include "server_debris.hpp"

namespace edgeland::net {

struct Server::Client {
  Client(std::uint32_t number, std::uint32_t enet_peer, const EditPolicy& p, Clock::time_point now)
      : id(number),
        peer(enet_peer),
        rate(p.edits_per_second, p.burst, now),
        repairs(p.repairs_per_second, p.repair_burst, now),
        flood(p.flood_limit) {}
  std::uint32_t id, peer;
  bool greeted = false;
  Role role = Role::kFull;
  bool watch_all = true;
  std::set<std::uint32_t> watched;  // region indices (when not watch_all)
  Box64 granted{{1, 1}, {0, 0}};
  RateLimiter rate, repairs;  // edits, repair requests
  FloodCounter flood;
  bool dropped = false;
  bool watches(std::uint32_t region) const { return watch_all || watched.count(region) != 0; }
};

namespace {

std::string record_of(const Landscape& w, const TreePath& path, bool content) {
  std::ostringstream out;
  if (content)
    w.save_region(path, out);
  else
    w.save_region_summary(path, out);
  return std::move(out).str();
}

bool inverted(const Box64& b) { return b.min.x > b.max.x || b.min.y > b.max.y; }

bool boxes_overlap(const Box64& a, const Box64& b) {
  return !inverted(a) && !inverted(b) && a.overlaps_open(b);
}

}  // namespace

Server::Server(Landscape world, ServerOptions options)
    : world_(std::move(world)), options_(std::move(options)) {
  if (world_.config().region_depth < 0)
    throw std::invalid_argument("edgeland serve needs a world with regions");
  regions_ = world_.region_paths();
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    std::uint32_t index = 0;
    for (const std::uint8_t d : regions_[i]) index = index * 4 + d;
    region_slot_[index] = i;
  }
  host_ = std::make_unique<EnetHost>(EnetHost::listen(
      options_.address, options_.port, options_.max_clients, options_.policy.max_packet));
  if (options_.debris) debris_ = std::make_unique<ServerDebris>(world_);
  sequence_ = options_.first_sequence;
  refresh_snapshot();
  next_checkpoint_ = Clock::now() + options_.checkpoint_every;
}

Server::~Server() = default;

std::uint16_t Server::port() const { return host_->port(); }

ServerStats Server::stats() const {
  ServerStats s = stats_;
  s.sequence = sequence_;
  s.bytes_sent = host_->bytes_sent();
  s.bytes_received = host_->bytes_received();
  return s;
}

void Server::step(int timeout_ms) {
  for (EnetHost::Event e = host_->service(timeout_ms); e.kind != EnetHost::Event::Kind::kNone;
       e = host_->service(0)) {
    if (e.kind == EnetHost::Event::Kind::kConnect) {
      clients_[e.peer] =
          std::make_unique<Client>(next_client_++, e.peer, options_.policy, Clock::now());
    } else if (e.kind == EnetHost::Event::Kind::kDisconnect) {
      stats_.leaves += clients_.erase(e.peer);
    } else {
      receive(e.peer, e.data);
    }
  }
  for (auto it = clients_.begin(); it != clients_.end();) {
    if (!it->second->dropped) {
      ++it;
      continue;
    }
    host_->drop(it->first);
    ++stats_.dropped;
    it = clients_.erase(it);
  }
  if (Clock::now() >= next_checkpoint_) checkpoint();
  host_->flush();
}

void Server::finish() {
  checkpoint();
  host_->disconnect_all();
  for (int i = 0; i < 50; ++i) host_->service(10);
}

// --- receiving ---------------------------------------------------------------------------------
void Server::receive(std::uint32_t peer, const std::string& bytes) {
  const auto it = clients_.find(peer);
  if (it == clients_.end()) return;
  Client& c = *it->second;
  Message m;
  try {
    m = decode_message(bytes);
  } catch (const ProtocolError& e) {
    return reject(c, 0, RejectReason::kMalformed, e.what());
  }
  if (const auto* hello_message = std::get_if<Hello>(&m)) return hello(c, *hello_message);
  if (!c.greeted) return reject(c, 0, RejectReason::kMalformed, "no HELLO first");
  if (const auto* e = std::get_if<EditRequest>(&m)) return edit(c, *e);
  if (const auto* h = std::get_if<HashesRequest>(&m)) return hashes(c, *h);
  if (const auto* p = std::get_if<PatchRequest>(&m)) return patch(c, *p);
  reject(c, 0, RejectReason::kMalformed, "a server's message sent by a client");
}

void Server::reject(Client& c, std::uint32_t number, RejectReason reason,
                    const std::string& message) {
  ++stats_.rejects[reason];
  send(c, Reject{number, reason, message});
  if (c.flood.add(Clock::now())) c.dropped = true;
}

void Server::send(Client& c, const Message& m) {
  if (c.dropped) return;
  host_->send(c.peer, encode_message(m));
}

// --- joining -----------------------------------------------------------------------------------
void Server::hello(Client& c, const Hello& m) {
  if (c.greeted || m.version != kProtocolVersion)
    return reject(c, 0, RejectReason::kMalformed, "a second HELLO or another protocol version");
  for (const std::uint32_t r : m.regions)
    if (!region_slot_.count(r)) return reject(c, 0, RejectReason::kMalformed, "no such region");
  // A server that owns some regions of a world serves only those.
  const auto held = [&](std::uint32_t r) {
    return world_.region_loaded(regions_[region_slot_[r]]);
  };
  const bool all_held = std::all_of(region_slot_.begin(), region_slot_.end(),
                                    [&](const auto& r) { return held(r.first); });
  if ((m.watch_all && !all_held) || !std::all_of(m.regions.begin(), m.regions.end(), held))
    return reject(c, 0, RejectReason::kNotPermitted, "a region this server does not hold");
  c.greeted = true;
  c.role = m.role;
  c.watch_all = m.watch_all;
  c.watched.insert(m.regions.begin(), m.regions.end());
  const bool taken = std::any_of(clients_.begin(), clients_.end(), [&](const auto& other) {
    return other.second.get() != &c && boxes_overlap(other.second->granted, m.edit_box);
  });
  const Box64& w = world_.world();
  if (!taken && permitted(w, m.edit_box) && !inverted(m.edit_box)) c.granted = m.edit_box;
  Welcome welcome{c.id, w, world_.config(), world_.next_id(), 0, c.granted, {}, {}};
  if (c.role == Role::kThin)
    welcome_thin(c, welcome);
  else
    welcome_full(c, welcome);
  ++stats_.joins;
}

// The snapshot's regions, then the logged COMMANDs after it that reach a watched region.
void Server::welcome_full(Client& c, Welcome& w) {
  w.sequence = snapshot_.sequence;
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    std::uint32_t index = 0;
    for (const std::uint8_t d : regions_[i]) index = index * 4 + d;
    const bool record = c.watches(index);
    w.regions.push_back({record, record ? snapshot_.records[i] : snapshot_.summaries[i]});
  }
  send(c, w);
  for (const Logged& l : log_)
    if (std::any_of(l.regions.begin(), l.regions.end(),
                    [&](std::uint32_t r) { return c.watches(r); }))
      host_->send(c.peer, l.message);
}

// A thin client starts from every polygon of its regions now.
void Server::welcome_thin(Client& c, Welcome& w) {
  w.sequence = sequence_;
  ChangeSet all;
  world_.polygons_in(world_.world(), [&](const PolygonView& v) {
    const std::vector<std::uint32_t> r = regions_of_box(v.cell);
    if (!r.empty() && c.watches(r.front()))
      all.added.push_back({v.id, v.material, *v.polygon, v.cell});
    return true;
  });
  std::sort(all.added.begin(), all.added.end(),
            [](const ChangeSet::Added& a, const ChangeSet::Added& b) { return a.id < b.id; });
  w.changes = encode_delta(changes_delta(world_, world_, sequence_, all));
  send(c, w);
}

// Records reused while a region's hash is unchanged.
void Server::refresh_snapshot() {
  Snapshot next;
  next.sequence = sequence_;
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    const std::uint64_t hash = world_.node_digest(regions_[i])->hash;
    const bool same = i < snapshot_.hashes.size() && snapshot_.hashes[i] == hash;
    next.hashes.push_back(hash);
    // A region another server owns has no record here, only its summary.
    std::string record;
    if (same)
      record = snapshot_.records[i];
    else if (world_.region_loaded(regions_[i]))
      record = record_of(world_, regions_[i], true);
    next.records.push_back(std::move(record));
    next.summaries.push_back(same ? snapshot_.summaries[i] : record_of(world_, regions_[i], false));
  }
  snapshot_ = std::move(next);
  log_.clear();
}

// --- edits -------------------------------------------------------------------------------------
void Server::edit(Client& c, const EditRequest& m) {
  if (!c.rate.take(Clock::now())) return reject(c, m.number, RejectReason::kRate, "over the rate");
  EditVerdict verdict = check_edit_request(world_, c.granted, options_.policy, m.delta);
  if (!verdict.accepted())
    return reject(c, m.number, verdict.refusal.reason, verdict.refusal.message);
  apply_and_broadcast(c, m.number, verdict);
}

void Server::apply_and_broadcast(Client& c, std::uint32_t number, EditVerdict& verdict) {
  const Landscape before = world_;
  const std::optional<ChangeSet> changes = apply_accepted(world_, verdict.edits, verdict.refusal);
  if (!changes) return reject(c, number, verdict.refusal.reason, verdict.refusal.message);
  ++sequence_;
  ++stats_.edits;
  broadcast(c.id, number, before, verdict.edits, *changes);
  if (debris_) detach_debris(*changes);
}

// Each detachment is an edit of its own (origin 0), with its own sequence number.
void Server::detach_debris(const ChangeSet& changes) {
  debris_->detach_all(world_, changes,
                      [&](const Landscape& before, const Edit& carve, const ChangeSet& detached) {
                        ++sequence_;
                        ++stats_.debris;
                        broadcast(0, 0, before, std::span(&carve, 1), detached);
                      });
}

void Server::broadcast(std::uint32_t origin, std::uint32_t number, const Landscape& before,
                       std::span<const Edit> edits, const ChangeSet& changes) {
  std::optional<Box64> box;
  for (const Edit& e : edits)
    if (const std::optional<Box64> b = bounding_box(e.shape.polygons())) {
      if (box)
        box->expand(*b);
      else
        box = b;
    }
  Logged logged{sequence_, box ? regions_of_box(*box) : std::vector<std::uint32_t>{}, {}};
  logged.message = encode_message(
      Command{origin, number, encode_delta(command_delta(before, world_, sequence_, edits))});
  for (auto& [peer, c] : clients_) {
    if (!c->greeted) continue;
    if (c->role == Role::kThin) {
      send_changes(*c, before, changes);
      continue;
    }
    // The origin hears of its own edit (applied to its stubs, that changes nothing there).
    const Client& client = *c;  // clang 14 cannot capture a structured binding
    if (c->id != origin && !std::any_of(logged.regions.begin(), logged.regions.end(),
                                        [&](std::uint32_t r) { return client.watches(r); }))
      continue;
    host_->send(peer, logged.message);
    ++stats_.commands_sent;
    stats_.command_bytes += logged.message.size();
  }
  log_.push_back(std::move(logged));
  if (log_.size() >= options_.snapshot_every) refresh_snapshot();
}

// The change set cut to the client's regions: with per-region ids an id names its region.
void Server::send_changes(Client& c, const Landscape& before, const ChangeSet& changes) {
  ChangeSet mine;
  for (const PolygonId id : changes.removed)
    if (c.watches(static_cast<std::uint32_t>(id >> kRegionIdBits))) mine.removed.push_back(id);
  for (const ChangeSet::Added& a : changes.added)
    if (c.watches(static_cast<std::uint32_t>(a.id >> kRegionIdBits))) mine.added.push_back(a);
  if (mine.empty()) return;
  send(c, Changes{encode_delta(changes_delta(before, world_, sequence_, mine))});
}

std::vector<std::uint32_t> Server::regions_of_box(const Box64& box) const {
  std::vector<std::uint32_t> out;
  for (const TreePath& p : world_.regions_meeting(box)) {
    std::uint32_t index = 0;
    for (const std::uint8_t d : p) index = index * 4 + d;
    out.push_back(index);
  }
  return out;
}

// --- checkpoints and repair --------------------------------------------------------------------
void Server::checkpoint() {
  for (auto& [peer, c] : clients_)
    if (c->greeted) send(*c, checkpoint_for(*c));
  ++stats_.checkpoints;
  next_checkpoint_ = Clock::now() + options_.checkpoint_every;
}

Checkpoint Server::checkpoint_for(const Client& c) {
  Checkpoint m{sequence_, world_.state_hash(), {}};
  for (const auto& [index, slot] : region_slot_) {
    if (!c.watches(index) || (c.watch_all && c.role == Role::kFull)) continue;
    const TreePath& p = regions_[slot];
    m.regions.emplace_back(
        index, c.role == Role::kThin ? world_.drawn_digest(p) : world_.node_digest(p)->hash);
  }
  return m;
}

void Server::hashes(Client& c, const HashesRequest& m) {
  if (const std::optional<Refusal> no = repair_refusal(c, m.paths, false))
    return reject(c, 0, no->reason, no->message);
  Digests d{m.request, {}};
  for (const TreePath& p : m.paths) d.digests.push_back(world_.node_digest(p));
  const std::string bytes = encode_message(d);
  stats_.repair_bytes += bytes.size();
  host_->send(c.peer, bytes);
}

void Server::patch(Client& c, const PatchRequest& m) {
  if (const std::optional<Refusal> no = repair_refusal(c, m.paths, true))
    return reject(c, 0, no->reason, no->message);
  try {
    const std::string bytes = encode_message(
        PatchReply{m.request, encode_delta(patch_delta(world_, sequence_, m.paths))});
    stats_.repair_bytes += bytes.size();
    host_->send(c.peer, bytes);
  } catch (const LandscapeError& e) {  // a region this server does not hold
    reject(c, 0, RejectReason::kMalformed, e.what());
  }
}

// Repair requests have a rate of their own (EditPolicy::repairs_per_second), then the checks.
std::optional<Refusal> Server::repair_refusal(Client& c, const std::vector<TreePath>& paths,
                                              bool patch) {
  if (!c.repairs.take(Clock::now()))
    return Refusal{RejectReason::kRate, "repair requests over the rate"};
  return check_repair_request(world_, paths, patch, options_.policy,
                              [&](const TreePath& p) { return may_patch(c, p); });
}

// A client watching every region may ask for any node; another only for nodes in its regions.
bool Server::may_patch(const Client& c, const TreePath& path) const {
  if (c.watch_all) return true;
  const std::size_t depth = static_cast<std::size_t>(world_.config().region_depth);
  if (path.size() < depth) return false;
  std::uint32_t index = 0;
  for (std::size_t i = 0; i < depth; ++i) index = index * 4 + path[i];
  return c.watches(index);
}

}  // namespace edgeland::net
