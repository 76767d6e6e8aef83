// Compiled by ctest (kernel.int128_without_native) as a compiler without 128-bit integers sees
// it (__SIZEOF_INT128__ undefined, as MSVC): the kernel's headers choose the portable Int128 by
// themselves (README.md, "Supported platforms"), and its predicates compile on it.
#include <type_traits>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/predicates.hpp"

static_assert(std::is_same_v<edgeland::Int128, edgeland::PortableInt128>);
static_assert(EDGELAND_NATIVE_INT128 == 0);

int main() { return edgeland::orient_det({0, 0}, {1, 0}, {0, 1}) == 1 ? 0 : 1; }
