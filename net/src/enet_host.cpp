#include "enet_host.hpp"

#include <enet/enet.h>

#include <stdexcept>
#include <utility>

namespace edgeland::net {
namespace {

// enet_initialize once per process (it is a no-op on Linux beyond bookkeeping).
void initialise() {
  static const bool done = [] {
    if (enet_initialize() != 0) throw std::runtime_error("enet_initialize failed");
    return true;
  }();
  (void)done;
}

ENetAddress address_of(const std::string& host, std::uint16_t port) {
  ENetAddress a{};
  if (enet_address_set_host_ip(&a, host.c_str()) != 0)
    throw std::runtime_error("not an IP address: " + host);
  a.port = port;
  return a;
}

}  // namespace

EnetHost EnetHost::listen(const std::string& host, std::uint16_t port, std::size_t peers,
                          std::size_t max_packet) {
  initialise();
  const ENetAddress a = address_of(host, port);
  ENetHost* h = enet_host_create(&a, peers, 1, 0, 0);
  if (!h) throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port));
  h->maximumPacketSize = max_packet;
  return EnetHost(h);
}

EnetHost EnetHost::connect(const std::string& host, std::uint16_t port, std::size_t max_packet) {
  initialise();
  ENetHost* h = enet_host_create(nullptr, 1, 1, 0, 0);
  if (!h) throw std::runtime_error("cannot create an ENet client host");
  h->maximumPacketSize = max_packet;
  EnetHost out(h);
  const ENetAddress a = address_of(host, port);
  if (!enet_host_connect(h, &a, 1, 0)) throw std::runtime_error("cannot connect to " + host);
  return out;
}

EnetHost::~EnetHost() {
  if (host_) enet_host_destroy(host_);
}

EnetHost::EnetHost(EnetHost&& other) noexcept
    : host_(std::exchange(other.host_, nullptr)),
      peers_(std::move(other.peers_)),
      next_peer_(other.next_peer_) {}

std::uint16_t EnetHost::port() const { return host_->address.port; }

EnetHost::Event EnetHost::service(int timeout_ms) {
  ENetEvent e;
  Event out;
  if (enet_host_service(host_, &e, static_cast<enet_uint32>(timeout_ms)) <= 0) return out;
  switch (e.type) {
    case ENET_EVENT_TYPE_CONNECT:
      out.kind = Event::Kind::kConnect;
      out.peer = next_peer_++;
      e.peer->data = reinterpret_cast<void*>(std::uintptr_t{out.peer});
      peers_[out.peer] = e.peer;
      // A peer that stops answering (a killed client, a dead server) is given up within 3-6 s
      // rather than ENet's 5-30 s.
      enet_peer_timeout(e.peer, 0, 3000, 6000);
      break;
    case ENET_EVENT_TYPE_RECEIVE:
      out.kind = Event::Kind::kReceive;
      out.peer = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(e.peer->data));
      out.data.assign(reinterpret_cast<const char*>(e.packet->data), e.packet->dataLength);
      enet_packet_destroy(e.packet);
      break;
    case ENET_EVENT_TYPE_DISCONNECT:
      out.kind = Event::Kind::kDisconnect;
      out.peer = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(e.peer->data));
      peers_.erase(out.peer);
      break;
    case ENET_EVENT_TYPE_NONE:
      break;
  }
  return out;
}

void EnetHost::send(std::uint32_t peer, std::string_view message) {
  const auto it = peers_.find(peer);
  if (it == peers_.end()) return;
  ENetPacket* p = enet_packet_create(message.data(), message.size(), ENET_PACKET_FLAG_RELIABLE);
  if (!p) throw std::runtime_error("cannot make an ENet packet");
  if (enet_peer_send(it->second, 0, p) != 0) enet_packet_destroy(p);
}

void EnetHost::flush() { enet_host_flush(host_); }

void EnetHost::drop(std::uint32_t peer) {
  const auto it = peers_.find(peer);
  if (it == peers_.end()) return;
  enet_peer_disconnect_now(it->second, 0);
  peers_.erase(it);
}

void EnetHost::disconnect_all() {
  for (auto& [id, peer] : peers_) enet_peer_disconnect_later(peer, 0);
}

std::uint64_t EnetHost::bytes_sent() const { return host_->totalSentData; }
std::uint64_t EnetHost::bytes_received() const { return host_->totalReceivedData; }

}  // namespace edgeland::net
