// The mirroring client (client.hpp; net/README.md).
#include "edgeland/net/client.hpp"

#include <sstream>
#include <stdexcept>

#include "enet_host.hpp"

namespace edgeland::net {
namespace {

using Clock = std::chrono::steady_clock;

// The digest of the polygons of one region a thin client holds (ids name their regions).
std::uint64_t mirror_digest(const DrawMirror& mirror, std::uint32_t region) {
  std::uint64_t sum = 0;
  for (const auto& [id, p] : mirror.polygons())
    if ((id >> kRegionIdBits) == region) sum += polygon_digest(id, p.material, p.polygon);
  return sum;
}

}  // namespace

Client::Client(ClientOptions options) : options_(std::move(options)), start_(Clock::now()) {
  host_ = std::make_unique<EnetHost>(
      EnetHost::connect(options_.address, options_.port, options_.max_packet));
}

Client::~Client() = default;

ClientStats Client::stats() const {
  ClientStats s = stats_;
  s.bytes_received = host_->bytes_received();
  s.bytes_sent = host_->bytes_sent();
  return s;
}

void Client::ask(const Message& m) { host_->send(peer_, encode_message(m)); }

void Client::send_raw(const std::string& bytes) {
  host_->send(peer_, bytes);
  host_->flush();
}

void Client::step(int timeout_ms) {
  for (EnetHost::Event e = host_->service(timeout_ms); e.kind != EnetHost::Event::Kind::kNone;
       e = host_->service(0)) {
    if (e.kind == EnetHost::Event::Kind::kConnect) peer_ = e.peer;
    if (e.kind == EnetHost::Event::Kind::kConnect)
      ask(Hello{kProtocolVersion, options_.role, options_.watch_all, options_.regions,
                options_.edit_box});
    if (e.kind == EnetHost::Event::Kind::kDisconnect) stats_.disconnected = true;
    if (e.kind == EnetHost::Event::Kind::kReceive) receive(e.data);
  }
  if (stats_.welcomed && editing_ && !stats_.disconnected) send_due_edits();
  host_->flush();
}

void Client::leave() {
  host_->disconnect_all();
  for (int i = 0; i < 100 && !stats_.disconnected; ++i) step(10);
}

void Client::receive(const std::string& bytes) {
  const Message m = decode_message(bytes);  // the server is trusted to speak the protocol
  if (const auto* w = std::get_if<Welcome>(&m)) return welcome(*w);
  if (const auto* c = std::get_if<Command>(&m)) return command(*c);
  if (const auto* c = std::get_if<Changes>(&m)) return changes(*c);
  if (const auto* c = std::get_if<Checkpoint>(&m)) return checkpoint(*c);
  if (const auto* d = std::get_if<Digests>(&m)) return digests(*d);
  if (const auto* p = std::get_if<PatchReply>(&m)) return patched(*p);
  if (const auto* r = std::get_if<Reject>(&m)) return rejected(*r);
}

// Edit numbers start at 1: a REJECT of number 0 refuses another request, a repair's when one is
// under way (over the repair rate): the next checkpoint that differs starts it again.
void Client::rejected(const Reject& r) {
  ++stats_.rejects[r.reason];
  if (r.number == 0) {
    search_.reset();
    return;
  }
  ++stats_.edits_rejected;
  pending_.erase(r.number);
}

// --- joining -----------------------------------------------------------------------------------
void Client::welcome(const Welcome& m) {
  id_ = m.client;
  granted_ = m.granted;
  stats_.sequence = m.sequence;
  stats_.welcomed = true;
  in_step_ = true;
  if (options_.role == Role::kThin) {
    mirror_.apply(decode_delta(m.changes));
    return;
  }
  std::vector<RegionSummary> summaries;
  for (const RegionPart& part : m.regions) {
    std::istringstream in(part.bytes);
    summaries.push_back(Landscape::read_region_summary(in));
  }
  world_.emplace(Landscape::from_regions(m.world, m.config, m.next_id, summaries));
  for (const RegionPart& part : m.regions) {
    if (!part.record) continue;
    std::istringstream in(part.bytes);
    world_->load_region(in);
  }
  if (!options_.watch_all) world_->set_unloaded_policy(UnloadedRegions::kSkip);
}

// --- following ---------------------------------------------------------------------------------
// A client that watches everything checks each step's hashes; one that has diverged applies
// without them, so it keeps up while it repairs.
void Client::command(const Command& m) {
  const Delta d = decode_delta(m.delta);
  const bool checks = options_.watch_all && in_step_;
  try {
    world_->apply_delta(d, {checks, checks});
  } catch (const DeltaMismatch&) {
    in_step_ = false;
    world_->apply_delta(d, {false, false});
  }
  stats_.sequence = d.header.sequence;
  ++stats_.commands;
  if (m.origin != id_ || !pending_.count(m.number)) return;
  const auto us =
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - pending_[m.number]);
  stats_.latencies_us.push_back(static_cast<std::uint32_t>(us.count()));
  ++stats_.edits_applied;
  pending_.erase(m.number);
}

void Client::changes(const Changes& m) {
  const Delta d = decode_delta(m.delta);
  mirror_.apply(d);
  stats_.sequence = d.header.sequence;
  ++stats_.changes;
}

void Client::checkpoint(const Checkpoint& m) {
  ++stats_.checkpoints;
  std::vector<TreePath> differ;
  bool same = true;
  if (options_.role == Role::kFull && options_.watch_all) {
    same = world_->state_hash() == m.hash;
    if (!same) differ.push_back({});
  }
  for (const auto& [index, hash] : m.regions) {
    if (region_hash(index) == hash) continue;
    same = false;
    differ.push_back(path_of(index));
  }
  in_step_ = same;
  if (same) {
    ++stats_.matched;
    return;
  }
  ++stats_.mismatched;
  if (options_.role == Role::kFull && !search_) start_repair(differ);
}

std::uint64_t Client::region_hash(std::uint32_t index) const {
  if (options_.role == Role::kThin) return mirror_digest(mirror_, index);
  const std::optional<NodeDigest> d = world_->node_digest(path_of(index));
  return d ? d->hash : 0;
}

TreePath Client::path_of(std::uint32_t index) const {
  const auto depth = static_cast<std::size_t>(world_ ? world_->config().region_depth : 0);
  TreePath path(depth);
  for (std::size_t i = depth; i-- > 0; index /= 4) path[i] = static_cast<std::uint8_t>(index % 4);
  return path;
}

// --- repair ------------------------------------------------------------------------------------
void Client::start_repair(const std::vector<TreePath>& starts) {
  search_.emplace(starts);
  ++stats_.repairs;
  ask(HashesRequest{next_request_++, search_->questions()});
}

void Client::digests(const Digests& m) {
  if (!search_) return;
  stats_.repair_bytes += encode_message(m).size();
  search_->answer(*world_, m.digests);
  ++stats_.repair_rounds;
  if (!search_->done()) return ask(HashesRequest{next_request_++, search_->questions()});
  ask(PatchRequest{next_request_++, search_->differing()});
}

void Client::patched(const PatchReply& m) {
  stats_.repair_bytes += encode_message(m).size();
  search_.reset();
  const Delta d = decode_delta(m.delta);
  try {
    world_->apply_delta(d, {false, options_.watch_all});
    in_step_ = true;
  } catch (const DeltaMismatch&) {
    // Something else differs too (or an edit crossed the repair): keep the patch, and the next
    // checkpoint starts another search.
    world_->apply_delta(d, {false, false});
  }
}

// --- edits -------------------------------------------------------------------------------------
void Client::send_due_edits() {
  const Box64& b = granted_;
  if (options_.edits_per_second == 0 || b.max.x - b.min.x < 100 || b.max.y - b.min.y < 100) return;
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start_).count();
  const auto due = static_cast<std::uint64_t>(ms) * options_.edits_per_second / 1000;
  if (!stream_) stream_.emplace(options_.seed, b);
  for (; edits_due_sent_ < due; ++edits_due_sent_) request(stream_->next());
}

std::uint32_t Client::request(const Edit& edit) { return request(std::span(&edit, 1)); }

std::uint32_t Client::request(std::span<const Edit> batch) {
  Delta d;
  d.header = {DeltaKind::kCommand, kAlgorithmVersion, world_ ? world_->world_hash() : 0, 0, 0, 0};
  d.edits.assign(batch.begin(), batch.end());
  const std::uint32_t number = next_edit_++;
  pending_[number] = Clock::now();
  ++stats_.edits_sent;
  ask(EditRequest{number, encode_delta(d)});
  return number;
}

void Client::diverge(const Edit& edit) { apply_edit(*world_, edit); }

}  // namespace edgeland::net
