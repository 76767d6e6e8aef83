#pragma once
// Internal to edgeland (validate() and the clipper), not part of the API: the per-thread
// scratch workspace. A ScratchVector<T> is a std::vector that takes its storage from the
// thread's spare arrays of element type T and gives it back when it dies; the large
// temporaries of operations called again and again (every stage's arrays, the edge list, the
// plane graph, the labels) all live in ScratchVectors.
//
// Why: glibc gives freed memory at the top of the heap back to the system once more than
// 128 KiB of it is free there (M_TRIM_THRESHOLD). An operation that allocates a few hundred KiB
// of arrays and frees them at the end therefore page-faults all of it in again on the next
// operation: on a 100-square checkerboard that was a fifth of the clipper's time, and on 1,000
// squares nearly half; and on small inputs the allocations themselves are a visible share
// (validate() builds a dozen arrays per call). Kept storage makes repeated operations - a game
// carving its landscape - reuse the same pages.
//
// How the spares are shared: each element type has a stack of at most kSpareSlots spare arrays
// per thread. A ScratchVector takes the top one (or none) and pushes its storage back when it
// dies. Scratch arrays live in nested scopes, so the pushes come in the reverse order of the
// takes: the next operation's first array gets the storage the last operation's first array
// had, and each use settles on storage of the size it needs. Two arrays alive at once never
// share storage, so nothing is ever aliased, whatever the nesting; no use needs a name of its
// own.
//
// What a thread keeps is bounded: arrays over kMaxKeptBytes are freed when they die, and at
// most kSpareSlots spares are kept per element type (a full stack drops its smallest). 32: a
// landscape cell's overlay has more than 16 arrays of points alive at once (the rings of a
// region with holes among them), and with 16 it freed and allocated some on every call.
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace edgeland::detail {

inline constexpr std::size_t kMaxKeptBytes = std::size_t{8} << 20;
inline constexpr std::size_t kSpareSlots = 32;

// The thread's spare arrays of element type T.
template <class T>
class SpareArrays {
 public:
  static std::vector<T> take() {
    SpareArrays& s = mine();
    if (s.count_ == 0) return {};
    return std::move(s.slots_[--s.count_]);
  }
  static void give_back(std::vector<T>& v) {
    if (v.capacity() == 0 || v.capacity() > kMaxKeptBytes / sizeof(T)) return;
    SpareArrays& s = mine();
    if (s.count_ < kSpareSlots) {
      s.slots_[s.count_++] = std::move(v);
      return;
    }
    auto smallest =
        std::min_element(s.slots_.begin(), s.slots_.end(),
                         [](const auto& a, const auto& b) { return a.capacity() < b.capacity(); });
    if (smallest->capacity() < v.capacity()) *smallest = std::move(v);
  }

 private:
  static SpareArrays& mine() {
    thread_local SpareArrays spares;
    return spares;
  }
  std::array<std::vector<T>, kSpareSlots> slots_;
  std::size_t count_ = 0;
};

template <class T>
class ScratchVector : public std::vector<T> {
 public:
  ScratchVector() : std::vector<T>(SpareArrays<T>::take()) { this->clear(); }
  // A copy takes scratch storage of its own (tests copy stage results; the library does not).
  ScratchVector(const ScratchVector& other) : ScratchVector() {
    this->assign(other.begin(), other.end());
  }
  ScratchVector& operator=(const ScratchVector& other) {
    if (this != &other) this->assign(other.begin(), other.end());
    return *this;
  }
  ScratchVector(ScratchVector&& other) noexcept : std::vector<T>(std::move(other)) {}
  // A move trades storage instead of freeing this one's: the moved-from vector is left empty
  // holding it and gives it back when it dies, so the thread keeps every array (a struct of
  // scratch arrays assigned from a function's result would otherwise drop its own each time).
  ScratchVector& operator=(ScratchVector&& other) noexcept {
    this->swap(other);
    other.clear();
    return *this;
  }
  using std::vector<T>::operator=;  // assigning a plain vector's contents
  ~ScratchVector() { SpareArrays<T>::give_back(*this); }
};

}  // namespace edgeland::detail
