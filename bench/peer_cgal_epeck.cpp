// CGAL with the exact kernel (Exact_predicates_exact_constructions_kernel): exact rational
// intersection points, rounded to integers only when converted back for the validity check.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "peer_cgal.hpp"

namespace edgeland::bench {

std::unique_ptr<Peer> make_cgal_epeck_peer() {
  return std::make_unique<CgalPeer<CGAL::Exact_predicates_exact_constructions_kernel>>(
      "cgal_epeck");
}

}  // namespace edgeland::bench
