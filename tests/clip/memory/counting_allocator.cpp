// The counting allocation functions of counting_allocator.hpp. malloc_usable_size would be
// glibc's, so each block carries its size in a header of max_align_t.
#include "counting_allocator.hpp"

#include <cstdlib>
#include <new>

namespace edgeland::test {

HeapCounters& heap_counters() {
  static HeapCounters counters;
  return counters;
}

}  // namespace edgeland::test

namespace {

constexpr std::size_t kHeader = alignof(std::max_align_t);

void* counted_alloc(std::size_t n) {
  auto* p = static_cast<unsigned char*>(std::malloc(n + kHeader));
  if (!p) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(p) = n;
  edgeland::test::HeapCounters& c = edgeland::test::heap_counters();
  c.in_use += n;
  ++c.allocations;
  if (c.in_use > c.peak) c.peak = c.in_use;
  return p + kHeader;
}

void counted_free(void* q) noexcept {
  if (!q) return;
  auto* p = static_cast<unsigned char*>(q) - kHeader;
  edgeland::test::heap_counters().in_use -= *reinterpret_cast<std::size_t*>(p);
  std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }
