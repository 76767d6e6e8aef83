#include "json_text.hpp"

namespace edgeland::log {

std::string json_string(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out.append(1, '\\').append(1, c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      out.append("\\u00").append(1, kHex[byte >> 4]).append(1, kHex[byte & 0xf]);
    }
  }
  return out + "\"";
}

}  // namespace edgeland::log
