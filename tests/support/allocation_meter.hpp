#pragma once
// The heap bytes a piece of code needs at its peak, and how many allocations it makes, measured
// by replacing the global allocation functions (allocation_meter.cpp; link it into an executable
// to use it, as the load fuzzer, the regression replay and the clip and load memory tests do).
// Not thread-safe: a fuzz target and a test run one thing at a time.
#include <cstddef>

namespace edgeland::fuzz {

// Heap bytes in use now (allocated with operator new and not yet freed).
std::size_t heap_in_use() noexcept;
// Allocations made so far (every form of operator new that returned a block).
std::size_t allocations_made() noexcept;

// The peak of heap bytes in use while `run` ran, beyond what was in use before it.
template <class F>
std::size_t peak_heap_during(F&& run);

namespace detail {
std::size_t start_peak() noexcept;  // resets the peak to what is in use, returns that
std::size_t peak() noexcept;
// An allocation that would bring the bytes in use past `budget` throws std::bad_alloc (0: none).
void set_budget(std::size_t budget) noexcept;
}  // namespace detail

template <class F>
std::size_t peak_heap_during(F&& run) {
  const std::size_t before = detail::start_peak();
  run();
  return detail::peak() - before;
}

// While it lives, an allocation past `bytes` in use throws std::bad_alloc: how the tests make
// memory run out at a chosen size.
class HeapBudget {
 public:
  explicit HeapBudget(std::size_t bytes) noexcept { detail::set_budget(bytes); }
  ~HeapBudget() { detail::set_budget(0); }
  HeapBudget(const HeapBudget&) = delete;
  HeapBudget& operator=(const HeapBudget&) = delete;
};

}  // namespace edgeland::fuzz
