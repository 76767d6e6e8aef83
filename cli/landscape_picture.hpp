#pragma once
// Pictures of a landscape (cairo), as PNG or SVG: every material in its colour
// (material_palette.hpp) on the dark background of empty space; optionally the cell lines, a
// legend of the materials (a column to the right of the world) and extra layers of lines or
// outlines drawn over the world (the game layer's surface chains, convex pieces and islands in
// `edgeland render`). Floating point is fine here: a picture is for looking at, and nothing is
// read back from it.
#include <stdexcept>
#include <string>
#include <vector>

#include "edgeland/demo/palette.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::cli {

// cairo could not make or write the picture; what() names the file and cairo's reason.
class PictureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Paths in world coordinates drawn over the landscape in one style, named in the legend.
struct PictureLayer {
  std::string label;
  demo::Rgb colour;
  double opacity = 1;
  double line_width = 1.5;  // pixels
  bool closed = true;       // close each path (outlines) or not (open chains)
  bool fill = false;        // fill closed paths (at a quarter of the opacity) under the line
  std::vector<std::vector<Point64>> paths{};
};

struct PictureOptions {
  // The long side of the world in pixels: the world's long side, kept within these bounds
  // (a 10 x 20 world is drawn 256 pixels high, an 8192 x 8192 one 2048 wide).
  int min_long_side = 256;
  int max_long_side = 2048;
  bool cells = false;   // draw the cell lines (Landscape::cells_in) as thin lines
  bool legend = false;  // a column right of the world naming the materials and layers
  std::vector<PictureLayer> layers{};
};

// Writes `path`. North (+y) is up. O(vertices + cells + layer points). Throws PictureError.
void write_landscape_png(const Landscape& landscape, const std::string& path,
                         const PictureOptions& options = {});
void write_landscape_svg(const Landscape& landscape, const std::string& path,
                         const PictureOptions& options = {});

}  // namespace edgeland::cli
