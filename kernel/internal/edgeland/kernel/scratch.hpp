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
// What a thread keeps is bounded: arrays over kMaxKeptBytes are freed when they die, at most
// kSpareSlots spares are kept per element type (a full stack drops its smallest), and at most
// kMaxSpareBytes in all, over every element type: an array that would pass it is freed. 32
// slots: a landscape cell's overlay has more than 16 arrays of points alive at once (the rings
// of a region with holes among them), and with 16 it freed and allocated some on every call.
// The total: a clip of 10^5-vertex operands lets dozens of 3-8 MB arrays die long before its
// last stage (noding's and snap rounding's), most of element types the later stages never
// take, and kept they stayed resident beside the live ones: about 50 of the 150 MB peak of
// combs of 10^5 vertices, 27 of 183 MB at zigzag stars (issue 28). Small operations, which the
// spares are for, keep far less than the total. 32 MiB: with 16, a clip of smooth stars of 10^5
// vertices, repeated, ran about 10% slower (most of the loss in building its edge list).
#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

namespace edgeland::detail {

inline constexpr std::size_t kMaxKeptBytes = std::size_t{8} << 20;
inline constexpr std::size_t kSpareSlots = 32;
inline constexpr std::size_t kMaxSpareBytes = std::size_t{32} << 20;

// The bytes of every spare array the thread keeps, over all element types.
inline std::size_t& spare_bytes() {
  thread_local std::size_t bytes = 0;
  return bytes;
}

// The thread's spare arrays of element type T.
template <class T>
class SpareArrays {
 public:
  static std::vector<T> take() {
    SpareArrays& s = mine();
    if (s.count_ == 0) return {};
    std::vector<T> v = std::move(s.slots_[--s.count_]);
    spare_bytes() -= bytes_of(v);
    return v;
  }
  static void give_back(std::vector<T>& v) {
    if (v.capacity() == 0 || v.capacity() > kMaxKeptBytes / sizeof(T)) return;
    SpareArrays& s = mine();
    if (s.count_ < kSpareSlots) {
      if (!fits(bytes_of(v))) return;
      spare_bytes() += bytes_of(v);
      s.slots_[s.count_++] = std::move(v);
      return;
    }
    auto smallest =
        std::min_element(s.slots_.begin(), s.slots_.end(),
                         [](const auto& a, const auto& b) { return a.capacity() < b.capacity(); });
    if (smallest->capacity() >= v.capacity() || !fits(bytes_of(v) - bytes_of(*smallest))) return;
    spare_bytes() += bytes_of(v) - bytes_of(*smallest);
    *smallest = std::move(v);
  }

 private:
  static std::size_t bytes_of(const std::vector<T>& v) { return v.capacity() * sizeof(T); }
  static bool fits(std::size_t more) { return spare_bytes() + more <= kMaxSpareBytes; }
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
  ScratchVector(std::initializer_list<T> items) : ScratchVector() { this->assign(items); }
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
  // The elements go first: a spare keeps storage, never live elements. An element that is a
  // scratch array itself (a ring of points) then gives its storage back while its own spares
  // still live, and no spare array is left holding one for the thread's exit, where spares are
  // destroyed in an order of their own (a ring in a spare gave back to destroyed spares of
  // points: a double free at exit, seen in game_tests).
  ~ScratchVector() {
    this->clear();
    SpareArrays<T>::give_back(*this);
  }
};

// Ends v's use before it dies: its storage goes where a dying ScratchVector's goes (a spare,
// within the bounds above, else freed) and v is left empty, with none. For a stage's result
// that the later stages of a long pipeline no longer read.
template <class T>
void discard(ScratchVector<T>& v) {
  ScratchVector<T> dead(std::move(v));
}

}  // namespace edgeland::detail
