#pragma once
// The one place ENet is called (net/README.md): a host that listens on or connects to a loopback
// or other address, and sends and receives whole messages reliably on channel 0.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

struct _ENetHost;
struct _ENetPeer;

namespace edgeland::net {

class EnetHost {
 public:
  // A server on `address`:`port` (port 0: a free one, port() says which) for up to `peers` peers;
  // an incoming message over `max_packet` bytes is refused by ENet. Throws std::runtime_error.
  static EnetHost listen(const std::string& address, std::uint16_t port, std::size_t peers,
                         std::size_t max_packet);
  // A client connecting to address:port: service() reports kConnect once the server answers.
  // Throws std::runtime_error.
  static EnetHost connect(const std::string& address, std::uint16_t port, std::size_t max_packet);
  ~EnetHost();
  EnetHost(EnetHost&& other) noexcept;
  EnetHost& operator=(EnetHost&&) = delete;
  EnetHost(const EnetHost&) = delete;
  EnetHost& operator=(const EnetHost&) = delete;

  std::uint16_t port() const;

  struct Event {
    enum class Kind { kNone, kConnect, kReceive, kDisconnect } kind = Kind::kNone;
    std::uint32_t peer = 0;  // the host's own number for the peer (1, 2, ...)
    std::string data;        // kReceive: the message
  };
  // Waits up to `timeout_ms` for one event (kNone when none came).
  Event service(int timeout_ms);
  // Reliable, ordered (channel 0). A peer that is gone is passed over.
  void send(std::uint32_t peer, std::string_view message);
  // Sends what is queued now.
  void flush();
  // Ends the connection at once (the peer learns it by timeout or its next send).
  void drop(std::uint32_t peer);
  // Asks the peer to disconnect after what is queued (a client leaving).
  void disconnect_all();

  std::uint64_t bytes_sent() const;
  std::uint64_t bytes_received() const;

 private:
  explicit EnetHost(_ENetHost* host) : host_(host) {}
  _ENetHost* host_;
  std::map<std::uint32_t, _ENetPeer*> peers_;
  std::uint32_t next_peer_ = 1;
};

}  // namespace edgeland::net
