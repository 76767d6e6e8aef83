#pragma once
// Per-thread reusable arrays for the pipeline's large temporaries.
//
// Why: glibc gives freed memory at the top of the heap back to the system once more than
// 128 KiB of it is free there (M_TRIM_THRESHOLD). An operation that allocates a few hundred KiB
// of arrays and frees them at the end therefore page-faults all of it in again on the next
// operation: on a 100-square checkerboard that was a fifth of the time, and on 1,000 squares
// nearly half. An array kept per thread keeps the capacity of the thread's largest operation
// (like the edge list, clip.cpp) and is handed out empty, so repeated operations - a game
// carving its landscape - reuse the same pages.
//
// Each call site names its own buffer with a tag type. A site must not be re-entered while its
// buffer is in use: no stage of the pipeline is recursive, and a stage that runs another one
// (hole splitting builds a plane graph) only does so after the other's earlier run returned.
#include <vector>

namespace edgeland::detail {

template <class Tag, class T>
std::vector<T>& thread_buffer() {
  thread_local std::vector<T> buffer;
  buffer.clear();
  return buffer;
}

}  // namespace edgeland::detail
