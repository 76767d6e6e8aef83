#pragma once
// The pixel peer of the landscape benchmarks (thesis chapter 5): a byte per unit square, the
// material of that square, as Clonk, Worms and Lemmings keep their worlds. It is the fairest
// rival we can write: shapes are rasterised by their exact region (scanline spans, no per-pixel
// point test), queries read bytes, a ray walks the squares it passes (integer DDA), a snapshot
// copies the array. Integer arithmetic only, so its answers can be compared with the
// landscape's exactly.
//
// The square (i, j) is the unit square [i, i+1] x [j, j+1]; it holds the material of its
// centre (i + 1/2, j + 1/2). A centre on a shape's boundary belongs to the face holding
// centre + eps (1, eps), the landscape's half-open rule (landscape.hpp, material_at).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::bench {

// Where a bitmap ray enters a solid square: the square, its material, and the ray's parameter
// there, t = t_num / t_den in [0, 1] (exact).
struct BitmapHit {
  Point64 square;
  Material material = kEmpty;
  std::int64_t t_num = 0;
  std::int64_t t_den = 1;
};

class BitmapWorld {
 public:
  // Local coordinates (relative to world.min) must stay within +-kMaxLocal so that the scanline
  // arithmetic fits int64; every byte starts as `fill`. Throws std::invalid_argument.
  static constexpr std::int64_t kMaxLocal = std::int64_t{1} << 28;
  BitmapWorld(const Box64& world, Material fill);

  // Every square whose centre lies in the shape (any valid polygon set; polygons with disjoint
  // interiors, so even-odd over all edges is their union) becomes `material`. Parts outside the
  // world are ignored. Throws std::invalid_argument for coordinates beyond kMaxLocal.
  void paint(const PolygonSet& shape, Material material);
  void carve(const PolygonSet& shape) { paint(shape, kEmpty); }
  void fill(const PolygonSet& shape, Material material) { paint(shape, material); }
  // Every square of material `from` whose centre lies in the shape becomes `to`.
  void replace(const PolygonSet& shape, Material from, Material to);

  // Copies the squares of the box (clipped to the world) from `source`, a world of the same
  // box: how the benchmarks undo an edit without copying the whole array.
  void restore(const BitmapWorld& source, const Box64& box);

  // The material of the square holding p + eps (1, eps), i.e. square (p.x, p.y); kEmpty outside.
  Material material_at(Point64 p) const;
  // Walks the squares the segment from -> to passes (the segment moved by eps (1, eps)) and
  // returns the first solid square of a material other than the start square's, as
  // Landscape::raycast culls back faces.
  std::optional<BitmapHit> raycast(Point64 from, Point64 to) const;
  // The solid materials of the squares whose interiors meet the box's interior, ascending.
  std::vector<Material> overlaps(const Box64& box) const;

  const Box64& world() const noexcept { return world_; }
  std::size_t bytes() const noexcept { return cells_.size(); }
  std::int64_t width() const noexcept { return width_; }
  std::int64_t height() const noexcept { return height_; }
  // The material numbers of row `y` (local: 0 <= y < height()), width() bytes: what a game's
  // contour tracer reads (bench/pixel_terrain.hpp).
  const std::uint8_t* row(std::int64_t y) const noexcept {
    return cells_.data() + static_cast<std::size_t>(y * width_);
  }

 private:
  // One non-horizontal edge as it crosses the scanlines y = row + 1/2 of the rows it spans:
  // the first square right of the crossing is ceil(q + r / den), stepped per row without
  // division.
  struct ScanEdge {
    std::int64_t first_row, last_row;
    std::int64_t q, r, den, step_q, step_r;
  };
  void collect_edges(const PolygonSet& shape);
  // The rows of the shape: each square in it of material `from` (any material when nullopt)
  // becomes `to`.
  void scan(const PolygonSet& shape, std::optional<Material> from, Material to);
  void fill_row(std::int64_t row, std::optional<Material> from, Material to);
  Material at_local(std::int64_t x, std::int64_t y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return kEmpty;
    return cells_[static_cast<std::size_t>(y * width_ + x)];
  }

  Box64 world_;
  std::int64_t width_ = 0, height_ = 0;
  std::vector<std::uint8_t> cells_;  // material numbers
  // Scratch of paint(), kept to spare the allocations as a game would.
  std::vector<ScanEdge> edges_;
  std::vector<std::int64_t> crossings_;
};

}  // namespace edgeland::bench
