// Boost.Geometry with double coordinates: its floating-point overlay path.
#include "peer_boost.hpp"

namespace edgeland::bench {

std::unique_ptr<Peer> make_boost_double_peer() {
  return std::make_unique<BoostPeer<double>>("boost_double");
}

}  // namespace edgeland::bench
