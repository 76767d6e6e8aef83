// libFuzzer target `load`: see run_load in decoders.hpp for what is decoded and checked.
// Mutations are both raw (libFuzzer's own, on the bytes) and structure-aware: half of them
// decode the save file, change a field, node, polygon or vertex, and write it back with a
// correct checksum (save_mutator.hpp), so that they reach load()'s rules (issue 27, point 4).
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "decoders.hpp"
#include "report.hpp"
#include "save_mutator.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  edgeland::fuzz::abort_on(edgeland::fuzz::run_load(data, size));
  return 0;
}

// Input: one flag byte (odd: fix the checksum), then the file.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  if (size > 1 && seed % 2 == 0) {
    const std::optional<std::string> mutated = edgeland::fuzz::mutate_save(
        std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1), seed / 2);
    if (mutated && mutated->size() + 1 <= max_size) {
      data[0] = 0;  // the checksum is already right
      std::memcpy(data + 1, mutated->data(), mutated->size());
      return mutated->size() + 1;
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}
