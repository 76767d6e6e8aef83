#pragma once
// The global allocation functions of clip_memory_tests, replaced to count: heap bytes in use and
// their peak (memory_bound_test.cpp), and the number of allocations (relabel_allocations_test.cpp).
// Replacing them is why these tests are an executable of their own (tests/CMakeLists.txt).
#include <cstddef>

namespace edgeland::test {

struct HeapCounters {
  std::size_t in_use = 0, peak = 0, allocations = 0;
};

// This executable's counters (every operator new and delete updates them).
HeapCounters& heap_counters();

}  // namespace edgeland::test
