// The `parse` target (decoders.hpp): the WKT reader and the log parser on arbitrary bytes.
#include <algorithm>
#include <exception>
#include <string_view>

#include "decoders.hpp"
#include "edgeland/io/clip_log.hpp"
#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::fuzz {

std::optional<Finding> run_parse(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const WktGeometry g = read_wkt(text);
    for (const WktPolygon& polygon : g.polygons) {
      std::vector<const Ring*> rings{&polygon.exterior};
      for (const Ring& hole : polygon.holes) rings.push_back(&hole);
      for (const Ring* ring : rings) {
        for (const Point64& p : *ring) {
          if (!in_range(p)) return Finding{"read_wkt returned an out-of-range point", ""};
        }
      }
    }
  } catch (const WktError&) {
    // the documented typed error
  } catch (const std::exception& e) {
    return Finding{std::string("read_wkt threw an untyped exception: ") + e.what(), ""};
  }
  try {
    const log::ParsedLog parsed = log::parse_log(text);
    if (parsed.error) {
      const std::size_t lines =
          static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
      if (parsed.error->line == 0 || parsed.error->line > lines) {
        return Finding{"log error names line " + std::to_string(parsed.error->line) + " of " +
                           std::to_string(lines),
                       ""};
      }
    }
  } catch (const std::exception& e) {
    return Finding{std::string("parse_log threw: ") + e.what(), ""};
  }
  return std::nullopt;
}

}  // namespace edgeland::fuzz
