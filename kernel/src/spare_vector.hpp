#pragma once
// Private to kernel/src: a std::vector that takes its storage from a per-thread spare and gives
// it back when it dies, for the arrays validate() builds on every call.
//
// Why: the clipper validates both operands of every operation, so on small inputs the
// allocations themselves are a visible share of validate() (a dozen arrays, several of them
// grown push by push); and glibc gives freed memory at the top of the heap back to the system
// once more than 128 KiB of it is free there (M_TRIM_THRESHOLD), so large arrays freed at the
// end of one call page-fault in again on the next. The spare keeps the capacity of the
// thread's largest call.
//
// Each use names its own spare with a tag type. The spare only holds storage while no vector
// of that tag is alive: a vector takes it whole (two live vectors of one tag simply do not
// share), and on destruction hands back its storage if that is larger. So nothing is ever
// aliased, whatever the nesting. (The clipper has the same device, clip/src/recycled_vector.hpp;
// the kernel cannot include it.)
#include <utility>
#include <vector>

namespace edgeland::detail {

template <class Tag, class T>
class SpareVector : public std::vector<T> {
 public:
  SpareVector() : std::vector<T>(std::move(spare())) { this->clear(); }
  SpareVector(const SpareVector&) = delete;
  SpareVector& operator=(const SpareVector&) = delete;
  ~SpareVector() {
    std::vector<T>& s = spare();
    if (this->capacity() > s.capacity()) s = std::move(static_cast<std::vector<T>&>(*this));
  }

 private:
  static std::vector<T>& spare() {
    thread_local std::vector<T> storage;
    return storage;
  }
};

}  // namespace edgeland::detail
