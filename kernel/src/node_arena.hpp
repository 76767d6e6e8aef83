#pragma once
// A monotonic arena and an allocator over it, for node-based containers that live as long as
// one computation (the sweep's status set): every allocation is a pointer bump in a block, and
// everything is released at once with the arena. std::pmr::monotonic_buffer_resource does the
// same, but Emscripten's libc++ (the browser build, TOOLCHAIN.md pitfall 16) has no
// <memory_resource>.
#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace edgeland::detail {

class NodeArena {
 public:
  NodeArena() = default;
  NodeArena(const NodeArena&) = delete;
  NodeArena& operator=(const NodeArena&) = delete;

  // `align` at most alignof(std::max_align_t): a block from new[], and the inline one, start
  // aligned for it.
  void* allocate(std::size_t bytes, std::size_t align) {
    std::size_t at = (used_ + align - 1) / align * align;
    if (at + bytes > block_size_) {
      // Blocks grow geometrically, as the standard monotonic resource's do.
      block_size_ = std::max(blocks_.empty() ? kFirstBlock : 2 * block_size_, bytes);
      blocks_.push_back(std::make_unique<std::byte[]>(block_size_));
      at = 0;
    }
    used_ = at + bytes;
    return (blocks_.empty() ? inline_.data() : blocks_.back().get()) + at;
  }

 private:
  static constexpr std::size_t kInlineBlock = 1024;  // a small polygon's sweep: no heap at all
  static constexpr std::size_t kFirstBlock = 4096;
  alignas(std::max_align_t) std::array<std::byte, kInlineBlock> inline_;
  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  std::size_t block_size_ = kInlineBlock;
  std::size_t used_ = 0;
};

// An allocator handing out memory from a NodeArena; deallocation does nothing (the arena frees
// everything when it goes).
template <class T>
struct ArenaAllocator {
  using value_type = T;
  NodeArena* arena;
  explicit ArenaAllocator(NodeArena* a) noexcept : arena(a) {}
  template <class U>
  ArenaAllocator(const ArenaAllocator<U>& other) noexcept : arena(other.arena) {}
  T* allocate(std::size_t n) { return static_cast<T*>(arena->allocate(n * sizeof(T), alignof(T))); }
  void deallocate(T*, std::size_t) noexcept {}
  template <class U>
  friend bool operator==(const ArenaAllocator& a, const ArenaAllocator<U>& b) noexcept {
    return a.arena == b.arena;
  }
};

}  // namespace edgeland::detail
