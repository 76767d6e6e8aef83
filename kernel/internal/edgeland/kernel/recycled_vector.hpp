#pragma once
// Internal to edgeland (validate() and the clipper), not part of the API and not installed
// (it lives in kernel/internal/, which only targets built in this tree see): a std::vector that
// takes its storage from a per-thread spare and gives it back when it dies, for the large
// temporaries of operations called again and again.
//
// Why: glibc gives freed memory at the top of the heap back to the system once more than
// 128 KiB of it is free there (M_TRIM_THRESHOLD). An operation that allocates a few hundred KiB
// of arrays and frees them at the end therefore page-faults all of it in again on the next
// operation: on a 100-square checkerboard that was a fifth of the clipper's time, and on 1,000
// squares nearly half; and on small inputs the allocations themselves are a visible share
// (validate() builds a dozen arrays per call). Recycled storage keeps the capacity of the
// thread's largest operation, so repeated operations - a game carving its landscape - reuse
// the same pages.
//
// Each use names its own spare with a tag type. The spare only holds storage while no vector
// of that tag is alive: a vector takes it whole (two live vectors of one tag - a stage run
// within another, or two grids at once - simply do not share), and on destruction hands back
// its storage if that is larger. So nothing is ever aliased, whatever the nesting.
#include <cstddef>
#include <utility>
#include <vector>

namespace edgeland::detail {

// What a thread keeps between operations is bounded: a spare (or one of the clipper's reused
// objects) is kept only up to this size. An operation whose arrays are larger frees them as
// before; at that size its own work outweighs the page faults. (A per-thread running total was
// tried: its bookkeeping on every construction cost 3% of a small operation.)
inline constexpr std::size_t kMaxKeptBytes = std::size_t{8} << 20;

template <class Tag, class T>
class RecycledVector : public std::vector<T> {
 public:
  RecycledVector() : std::vector<T>(std::move(spare())) { this->clear(); }
  RecycledVector(const RecycledVector&) = delete;
  RecycledVector& operator=(const RecycledVector&) = delete;
  RecycledVector(RecycledVector&& other) noexcept : std::vector<T>(std::move(other)) {}
  RecycledVector& operator=(RecycledVector&& other) noexcept {
    std::vector<T>::operator=(std::move(other));
    return *this;
  }
  using std::vector<T>::operator=;  // assigning a plain vector's contents
  ~RecycledVector() {
    std::vector<T>& s = spare();
    if (this->capacity() > s.capacity() && this->capacity() <= kMaxKeptBytes / sizeof(T))
      s = std::move(static_cast<std::vector<T>&>(*this));
  }

 private:
  static std::vector<T>& spare() {
    thread_local std::vector<T> storage;
    return storage;
  }
};

}  // namespace edgeland::detail
