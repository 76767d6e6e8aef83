#include "allocation_meter.hpp"

#include <cstdlib>
#include <new>

namespace {

// Each block carries its size in a header of max_align_t (malloc_usable_size would be glibc's).
std::size_t g_in_use = 0, g_peak = 0, g_budget = 0, g_allocations = 0;
constexpr std::size_t kHeader = alignof(std::max_align_t);

void* counted_alloc(std::size_t n) {
  if (g_budget != 0 && g_in_use + n > g_budget) throw std::bad_alloc();
  auto* p = static_cast<unsigned char*>(std::malloc(n + kHeader));
  if (!p) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(p) = n;
  g_in_use += n;
  ++g_allocations;
  if (g_in_use > g_peak) g_peak = g_in_use;
  return p + kHeader;
}

void counted_free(void* q) noexcept {
  if (!q) return;
  auto* p = static_cast<unsigned char*>(q) - kHeader;
  g_in_use -= *reinterpret_cast<std::size_t*>(p);
  std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }
// The nothrow forms too (std::stable_sort's temporary buffer takes one): left to the runtime
// (AddressSanitizer replaces them all), their blocks would come back to counted_free without a
// header.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept {
  return operator new(n, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { counted_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { counted_free(p); }

namespace edgeland::fuzz {

std::size_t heap_in_use() noexcept { return g_in_use; }
std::size_t allocations_made() noexcept { return g_allocations; }

namespace detail {
std::size_t start_peak() noexcept {
  g_peak = g_in_use;
  return g_in_use;
}
std::size_t peak() noexcept { return g_peak; }
void set_budget(std::size_t budget) noexcept { g_budget = budget; }
}  // namespace detail

}  // namespace edgeland::fuzz
