// libFuzzer target `net_message`: see run_net_message in decoders.hpp for what is decoded and
// checked.
#include <cstddef>
#include <cstdint>

#include "decoders.hpp"
#include "report.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  edgeland::fuzz::abort_on(edgeland::fuzz::run_net_message(data, size));
  return 0;
}
