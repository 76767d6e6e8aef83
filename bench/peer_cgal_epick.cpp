// CGAL with the inexact-constructions kernel (Exact_predicates_inexact_constructions_kernel):
// exact predicates on double intersection points. CGAL's documentation asks for exact
// constructions in Boolean operations; the benchmark runs it anyway and records failures.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "peer_cgal.hpp"

namespace edgeland::bench {

std::unique_ptr<Peer> make_cgal_epick_peer() {
  return std::make_unique<CgalPeer<CGAL::Exact_predicates_inexact_constructions_kernel>>(
      "cgal_epick");
}

}  // namespace edgeland::bench
