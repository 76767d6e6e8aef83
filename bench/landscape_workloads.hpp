#pragma once
// The landscape's edit workloads (bench/README.md, "Landscape"), shared by the benchmark and by
// edgeland_landscape_profile (instructions and allocations per edit): seeded edits on an
// 8192 x 8192 world of material 1, every shape a ValidSet built before any clock starts.
//
//   carve: 32-gons of radius 40 at random centres.
//   dig:   a tunnel digger: capsule strokes of radius 20 (32-gon caps) along a random walk,
//          10 units per step.
//   fill:  32-gons of radius 40 of material 2 at other centres, filled into the world `carve`
//          leaves (run the carve workload first).
//   spot:  edits repeated at one spot: n-gons of 16-48 sides and radius 3-200 around centres
//          within 8 units of the world's centre, three in four carved and one in four filled
//          with material 2 (a turret shooting at one place, a pit dug and refilled).
//   pit:   the same at an arbitrary spot (3001, 2717) with small shapes, radius 3-30: the
//          held-out logs of issue 28 ("edits repeated at one spot", a world of a few hundred
//          vertices), where the cost is not the world's size (bench/README.md says what it is).
//   hotspot: mixed edits at one spot (issue 35's held-out hot spot): 7-32-gons of radius 5-60
//          around centres within 8 units of the world's centre (a quadtree corner at every
//          depth), in turn carved, filled with material 2, and replaced from 2 back to 1, in a
//          seeded order.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "landscape_common.hpp"

namespace edgeland::bench {

inline constexpr std::int64_t kEditWorldSide = 8192;
inline constexpr Box64 kEditWorld{{0, 0}, {kEditWorldSide, kEditWorldSide}};

enum class Workload : std::uint8_t { kCarve, kDig, kFill, kSpot, kPit, kHotSpot };
inline constexpr Workload kWorkloads[] = {Workload::kCarve, Workload::kDig, Workload::kFill,
                                          Workload::kSpot,  Workload::kPit, Workload::kHotSpot};
const char* workload_name(Workload w);
std::optional<Workload> workload_named(const std::string& name);

// The first n edits of the workload (the same edits for every n that covers them).
std::vector<Edit> workload_edits(Workload w, std::size_t n);

}  // namespace edgeland::bench
