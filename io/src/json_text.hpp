#pragma once
// Writing the replay's JSON by hand: a handful of fields does not need a JSON library, and io/
// depends on nothing beyond edgeland (io/README.md).
#include <string>
#include <string_view>

namespace edgeland::log {

// `text` as a JSON string literal, quotes included: '"', '\' and control characters escaped,
// and every byte outside printable ASCII as \u00XX, so that any bytes (a junk log's excerpt)
// give valid JSON.
std::string json_string(std::string_view text);

}  // namespace edgeland::log
