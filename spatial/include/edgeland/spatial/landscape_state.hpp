#pragma once
// A landscape's whole state as one value (spatial/README.md): the private member of Landscape
// (landscape.hpp), and the argument spatial/src's stages take from its members. Here, apart from
// the front end, so that the stages need not include it.
#include <array>
#include <cstdint>
#include <memory>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

struct Node;     // the tree (spatial/src/node.hpp)
struct LogLine;  // the recorded log, a persistent list shared by copies (spatial/src/edit_log.hpp)
using AreaTable = std::array<Int128, kMaterialCount>;

// An edit builds the next state from the current one and Landscape::apply commits it by one
// assignment, so a throw leaves the landscape as it was.
struct LandscapeState {
  Box64 world;
  LandscapeConfig config;
  LandscapeLimits limits;
  std::shared_ptr<const Node> root;
  std::shared_ptr<const AreaTable> areas;  // twice the area of every solid material
  PolygonId next_id = 1;
  std::uint64_t edits = 0;  // successful edits since construction (or load)
  Material initial_fill = kEmpty;
  bool checked = false;
  bool logging = false;
  UnloadedRegions unloaded = UnloadedRegions::kRefuse;  // what edits do at a stub
  std::shared_ptr<const LogLine> log;                   // the last line recorded
};

}  // namespace edgeland::detail
