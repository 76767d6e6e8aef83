#include "peer.hpp"

namespace edgeland::bench {

std::vector<std::unique_ptr<Peer>> make_all_peers() {
  std::vector<std::unique_ptr<Peer>> peers;
  peers.push_back(make_edgeland_peer());
  peers.push_back(make_edgeland_valid_peer());
  peers.push_back(make_boost_int64_peer());
  peers.push_back(make_boost_double_peer());
  peers.push_back(make_clipper1_peer());
  peers.push_back(make_geos_peer());
  peers.push_back(make_cgal_epeck_peer());
  peers.push_back(make_cgal_epick_peer());
  return peers;
}

}  // namespace edgeland::bench
