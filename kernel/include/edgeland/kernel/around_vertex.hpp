#pragma once
// Which of several directions out of a vertex a rotation meets first: the step of tracing a
// face of a plane graph (the next edge is the first one clockwise from the way back), with
// parts of the plane around the vertex that the rotation may not cross. The game layer traces
// surfaces cell by cell with it (game/README.md): a cell only sees its own edges, so the sweep
// must stop where a neighbouring cell's part of the plane begins. Exact: orientation tests only.
#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {

// The eight places a nonzero direction can point, counter-clockwise from +x: the axis rays are
// the even slots (0: +x, 2: +y, 4: -x, 6: -y), the open quadrants between them the odd ones
// (1: x > 0 and y > 0, 3: x < 0 < y, 5: x < 0 and y < 0, 7: y < 0 < x).
EDGELAND_EXPORT int direction_slot(Point64 d) noexcept;

// The open quadrants a sweep may not enter: blocked[q] for slot 2q + 1.
using BlockedQuadrants = std::array<bool, 4>;

// Sweeping clockwise from `from` (not included: a direction equal to it is met last, after a full
// turn), the index in `directions` of the first one met; nullopt when none is met before the
// sweep enters a blocked quadrant (the quadrant of `from` itself is never entered, it is left).
// Directions are nonzero and pairwise distinct (as directions). O(n), n = directions.size().
EDGELAND_EXPORT std::optional<std::size_t> first_clockwise(Point64 from,
                                                           std::span<const Point64> directions,
                                                           const BlockedQuadrants& blocked = {});

// The same, sweeping counter-clockwise.
EDGELAND_EXPORT std::optional<std::size_t> first_counterclockwise(
    Point64 from, std::span<const Point64> directions, const BlockedQuadrants& blocked = {});

}  // namespace edgeland
