#pragma once
// Structure-aware mutation of landscape save files for the load fuzzer (issue 27, point 4): the
// file is decoded into its fields (save_file.hpp), one field, node, polygon or vertex is changed
// the way a hostile or damaged file would differ, and it is written back with a correct
// checksum, so the mutation reaches load()'s rules instead of stopping at the checksum.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace edgeland::fuzz {

// `file` with one structural change chosen by `seed`; nothing when it does not decode.
std::optional<std::string> mutate_save(std::string_view file, std::uint32_t seed);

}  // namespace edgeland::fuzz
