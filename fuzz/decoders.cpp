// The fuzz targets by name (decoders.hpp): each target's decoding and checks live in its own
// file (clip_pair_decoders.cpp, clip_sequence_decoders.cpp, normalize_decoders.cpp,
// parse_decoders.cpp, landscape_decoders.cpp, polygon_decoders.cpp, game_decoders.cpp,
// delta_decoders.cpp, int128_decoders.cpp, net_decoders.cpp).
#include "decoders.hpp"

#include <exception>

namespace edgeland::fuzz {

Runner runner_for(std::string_view target) {
  if (target == "clip_pair") return run_clip_pair;
  if (target == "clip_sequence") return run_clip_sequence;
  if (target == "normalize") return run_normalize;
  if (target == "parse") return run_parse;
  if (target == "edit_sequence") return run_edit_sequence;
  if (target == "load") return run_load;
  if (target == "polygon_pieces") return run_polygon_pieces;
  if (target == "game_sequence") return run_game_sequence;
  if (target == "delta") return run_delta;
  if (target == "int128_portable") return run_int128_portable;
#ifdef EDGELAND_FUZZ_NET
  if (target == "net_message") return run_net_message;
#endif
  return nullptr;
}

std::vector<std::string> seeds_for(std::string_view target) {
  if (target == "delta") return delta_seeds();
#ifdef EDGELAND_FUZZ_NET
  if (target == "net_message") return net_message_seeds();
#endif
  return {};
}

std::string input_as_log(std::string_view target, const std::uint8_t* data, std::size_t size) {
  try {
    if (target == "clip_pair") return clip_pair_log(data, size);
    if (target == "clip_sequence") return clip_sequence_log(data, size);
    if (target == "edit_sequence") return edit_sequence_log(data, size);
  } catch (const std::exception&) {
    // decoding itself failed: there is no log to give
  }
  return "";
}

}  // namespace edgeland::fuzz
