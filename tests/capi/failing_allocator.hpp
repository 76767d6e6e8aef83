#pragma once
// Allocation-failure injection, in the manner of SQLite's and libxml2's test suites: the global
// allocation functions are replaced (failing_allocator.cpp; link it into an executable of its
// own) by ones that throw std::bad_alloc (or return NULL, the nothrow forms) once this thread's
// countdown runs out. Disarmed, they are malloc and free, so the test framework is unaffected.
#include <cstddef>

namespace edgeland::test {

enum class FaultMode {
  kOnce,        // the chosen allocation fails, those after it succeed (a transient shortage)
  kPersistent,  // the chosen allocation and every later one fail (memory gone for good)
};

// Arms this thread: allocations 0 .. skip - 1 from now succeed, allocation `skip` fails.
void arm_allocation_fault(std::size_t skip, FaultMode mode) noexcept;
// Disarms this thread; whether an allocation failed since arm_allocation_fault.
bool disarm_allocation_fault() noexcept;

}  // namespace edgeland::test
