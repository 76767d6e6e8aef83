// Boost.Geometry with int64 coordinates: its integer overlay path.
#include <cstdint>

#include "peer_boost.hpp"

namespace edgeland::bench {

std::unique_ptr<Peer> make_boost_int64_peer() {
  return std::make_unique<BoostPeer<std::int64_t>>("boost_int64");
}

}  // namespace edgeland::bench
