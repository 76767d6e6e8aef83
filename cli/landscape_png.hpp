#pragma once
// A picture of a landscape as a PNG file (cairo): every material in its colour
// (material_palette.hpp) on the dark background of empty space, optionally the cell lines.
// Floating point is fine here: a picture is for looking at, and nothing is read back from it.
#include <stdexcept>
#include <string>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::cli {

// cairo could not make or write the picture; what() names the file and cairo's reason.
class PngError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PngOptions {
  // The long side of the picture in pixels: the world's long side, kept within these bounds
  // (a 10 x 20 world is drawn 256 pixels high, an 8192 x 8192 one 2048 wide).
  int min_long_side = 256;
  int max_long_side = 2048;
  bool cells = false;  // draw the cell lines (Landscape::cells_in) as thin lines
};

// Writes `path`. North (+y) is up. O(vertices + cells). Throws PngError.
void write_landscape_png(const Landscape& landscape, const std::string& path,
                         const PngOptions& options = {});

}  // namespace edgeland::cli
