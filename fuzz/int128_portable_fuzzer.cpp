// libFuzzer target `int128_portable`: see run_int128_portable in decoders.hpp for what is decoded
// and checked.
#include <cstddef>
#include <cstdint>

#include "decoders.hpp"
#include "report.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  edgeland::fuzz::abort_on(edgeland::fuzz::run_int128_portable(data, size));
  return 0;
}
