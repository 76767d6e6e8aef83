#include "cell_tracker.hpp"

#include <algorithm>

namespace edgeland::cli {
namespace {

// Closed boxes whose interiors meet (sharing a side is not enough).
bool interiors_meet(const Box64& a, const Box64& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

}  // namespace

void CellTracker::apply(const ChangeSet& changes) {
  if (changes.cells.empty()) return;
  Box64 reach = changes.cells.front();
  for (const Box64& cell : changes.cells) reach.expand(cell);
  const auto replaced = [&](const Box64& old) {
    if (!interiors_meet(old, reach)) return false;
    return std::any_of(changes.cells.begin(), changes.cells.end(),
                       [&](const Box64& cell) { return interiors_meet(old, cell); });
  };
  std::erase_if(cells_, replaced);
  cells_.insert(cells_.end(), changes.cells.begin(), changes.cells.end());
}

}  // namespace edgeland::cli
