#include "failing_allocator.hpp"

#include <cstdlib>
#include <new>

namespace {

// This thread's countdown: plain thread-locals, constant-initialised, so reading them never
// allocates (a thread_local with a constructor could).
thread_local bool t_armed = false;
thread_local bool t_persistent = false;
thread_local bool t_fired = false;
thread_local std::size_t t_skip = 0;

// Whether this allocation is the one (or, persistent, one of those) chosen to fail.
bool fault_now() noexcept {
  if (!t_armed) return false;
  if (t_skip > 0) {
    --t_skip;
    return false;
  }
  t_fired = true;
  t_armed = t_persistent;
  return true;
}

void* allocate(std::size_t n) {
  if (fault_now()) throw std::bad_alloc();
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void* allocate_aligned(std::size_t n, std::align_val_t alignment) {
  if (fault_now()) throw std::bad_alloc();
  // aligned_alloc takes a multiple of the alignment (C17).
  const auto a = static_cast<std::size_t>(alignment);
  void* p = std::aligned_alloc(a, (n / a + 1) * a);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

// The nothrow forms report the same fault by NULL (std::stable_sort's buffer takes one).
template <class Allocate>
void* or_null(Allocate&& allocate_block) noexcept {
  try {
    return allocate_block();
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

}  // namespace

namespace edgeland::test {

void arm_allocation_fault(std::size_t skip, FaultMode mode) noexcept {
  t_skip = skip;
  t_persistent = mode == FaultMode::kPersistent;
  t_fired = false;
  t_armed = true;
}

bool disarm_allocation_fault() noexcept {
  t_armed = false;
  return t_fired;
}

}  // namespace edgeland::test

// Every replaceable form, so no block from one allocator reaches another's free (AddressSanitizer
// replaces them all too, and would see its own new paired with this file's free).
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return or_null([&] { return allocate(n); });
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return or_null([&] { return allocate(n); });
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return or_null([&] { return allocate_aligned(n, a); });
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return or_null([&] { return allocate_aligned(n, a); });
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
