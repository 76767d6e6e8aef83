#pragma once
// The edits a test client makes, and their replay in one process (the two-server test compares
// the two): blobs of radius 8-40 inside a box, carved, filled with material 1-3, or filled with 4
// where empty. The same seed and box give the same edits everywhere (integers only).
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::net {

class EDGELAND_EXPORT EditStream {
 public:
  // `box` must be at least 100 wide and high.
  EditStream(std::uint64_t seed, const Box64& box) : random_(seed), box_(box) {}
  Edit next();

 private:
  std::uint64_t random() { return random_.next(); }
  SplitMix64 random_;
  Box64 box_;
};

}  // namespace edgeland::net
