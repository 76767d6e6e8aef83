#include "bitmap_world.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace edgeland::bench {
namespace {

// Floor division for den > 0 (C++ truncates toward zero).
std::int64_t floor_div(std::int64_t num, std::int64_t den) {
  const std::int64_t q = num / den;
  return (num % den != 0 && num < 0) ? q - 1 : q;
}

void require_local(std::int64_t c) {
  if (c < -BitmapWorld::kMaxLocal || c > BitmapWorld::kMaxLocal)
    throw std::invalid_argument("bitmap world: coordinate " + std::to_string(c) +
                                " too far from the world");
}

}  // namespace

BitmapWorld::BitmapWorld(const Box64& world, Material fill)
    : world_(world), width_(world.max.x - world.min.x), height_(world.max.y - world.min.y) {
  if (width_ <= 0 || height_ <= 0 || width_ > kMaxLocal || height_ > kMaxLocal)
    throw std::invalid_argument("bitmap world: unusable world box");
  cells_.assign(static_cast<std::size_t>(width_ * height_), fill.value());
}

// The scanline y = row + 1/2 never meets a vertex (integer y), so every edge it crosses is
// crossed once, strictly inside. In doubled coordinates the crossing is at x with
// 2x - 1 = N / den, N = 2 x0 dy + (2 row + 1 - 2 y0) dx - dy, den = 2 dy; the squares right of
// it (centre + eps at or past x) start at ceil(N / den).
void BitmapWorld::collect_edges(const PolygonSet& shape) {
  edges_.clear();
  for (const Polygon& polygon : shape) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      Point64 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      a = {a.x - world_.min.x, a.y - world_.min.y};
      b = {b.x - world_.min.x, b.y - world_.min.y};
      require_local(a.x);
      require_local(a.y);
      if (a.y == b.y) continue;  // horizontal: no scanline crosses it
      if (a.y > b.y) std::swap(a, b);
      const std::int64_t first = std::max<std::int64_t>(a.y, 0);
      const std::int64_t last = std::min(b.y - 1, height_ - 1);
      if (first > last) continue;
      const std::int64_t dx = b.x - a.x, dy = b.y - a.y, den = 2 * dy;
      const std::int64_t n = 2 * a.x * dy + (2 * first + 1 - 2 * a.y) * dx - dy;
      const std::int64_t q = floor_div(n, den), step_q = floor_div(2 * dx, den);
      edges_.push_back({first, last, q, n - q * den, den, step_q, 2 * dx - step_q * den});
    }
  }
  std::sort(edges_.begin(), edges_.end(),
            [](const ScanEdge& e, const ScanEdge& f) { return e.first_row < f.first_row; });
}

// Even-odd spans between the sorted crossings of one row, clipped to the world.
void BitmapWorld::fill_row(std::int64_t row, std::optional<Material> from, Material to) {
  std::sort(crossings_.begin(), crossings_.end());
  std::uint8_t* line = cells_.data() + row * width_;
  for (std::size_t k = 0; k + 1 < crossings_.size(); k += 2) {
    const std::int64_t first = std::max<std::int64_t>(crossings_[k], 0);
    const std::int64_t end = std::min(crossings_[k + 1], width_);
    if (first >= end) continue;
    if (!from) {
      std::memset(line + first, to.value(), static_cast<std::size_t>(end - first));
      continue;
    }
    for (std::int64_t x = first; x < end; ++x)
      if (line[x] == from->value()) line[x] = to.value();
  }
}

void BitmapWorld::paint(const PolygonSet& shape, Material material) {
  scan(shape, std::nullopt, material);
}

void BitmapWorld::replace(const PolygonSet& shape, Material from, Material to) {
  scan(shape, from, to);
}

// An active-edge scan: edges enter at their first row (sorted), each row takes the crossing of
// every active edge, steps it exactly, and drops it after its last row.
void BitmapWorld::scan(const PolygonSet& shape, std::optional<Material> from, Material to) {
  collect_edges(shape);
  std::size_t next = 0, active_end = 0;  // edges_[0, active_end) : entered, maybe finished
  std::int64_t row = edges_.empty() ? 0 : edges_.front().first_row;
  while (next < edges_.size() || active_end > 0) {
    while (next < edges_.size() && edges_[next].first_row == row)
      std::swap(edges_[active_end++], edges_[next++]);
    crossings_.clear();
    for (std::size_t i = 0; i < active_end;) {
      ScanEdge& e = edges_[i];
      crossings_.push_back(e.q + (e.r > 0 ? 1 : 0));
      e.q += e.step_q;
      e.r += e.step_r;
      if (e.r >= e.den) {
        e.r -= e.den;
        ++e.q;
      }
      if (e.last_row == row)
        std::swap(e, edges_[--active_end]);
      else
        ++i;
    }
    fill_row(row, from, to);
    if (active_end == 0 && next < edges_.size())
      row = edges_[next].first_row;
    else
      ++row;
  }
}

void BitmapWorld::restore(const BitmapWorld& source, const Box64& box) {
  const std::int64_t x0 = std::max(box.min.x - world_.min.x, std::int64_t{0});
  const std::int64_t x1 = std::min(box.max.x - world_.min.x, width_);
  for (std::int64_t y = std::max(box.min.y - world_.min.y, std::int64_t{0});
       y < std::min(box.max.y - world_.min.y, height_); ++y) {
    if (x0 < x1)
      std::memcpy(cells_.data() + y * width_ + x0, source.cells_.data() + y * width_ + x0,
                  static_cast<std::size_t>(x1 - x0));
  }
}

Material BitmapWorld::material_at(Point64 p) const {
  return at_local(p.x - world_.min.x, p.y - world_.min.y);
}

// Integer DDA (Amanatides-Woo): the next x line is reached at t = nx / |dx|, the next y line at
// ny / |dy|, compared by cross-multiplication. The segment moved by eps (1, eps) starts in
// square (from.x, from.y); on a tie (a lattice corner) it crosses the x line first when going
// right (its eps x-offset brings that line closer) and the y line first when going left.
std::optional<BitmapHit> BitmapWorld::raycast(Point64 from, Point64 to) const {
  const std::int64_t dx = to.x - from.x, dy = to.y - from.y;
  const std::int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
  const std::int64_t sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
  std::int64_t x = from.x - world_.min.x, y = from.y - world_.min.y;
  const Material start = at_local(x, y);
  std::int64_t nx = dx > 0 ? 1 : 0, ny = dy > 0 ? 1 : 0;  // distance to the next line, in units
  for (std::int64_t steps = adx + ady; steps > 0; --steps) {
    const std::int64_t lhs = nx * ady, rhs = ny * adx;  // t_x * |dx||dy| vs t_y * |dx||dy|
    const bool step_x = ady == 0 || (adx != 0 && (lhs < rhs || (lhs == rhs && dx > 0)));
    BitmapHit hit;
    if (step_x) {
      x += sx;
      hit = {{}, kEmpty, nx, adx};
      ++nx;
    } else {
      y += sy;
      hit = {{}, kEmpty, ny, ady};
      ++ny;
    }
    const Material m = at_local(x, y);
    if (m != kEmpty && m != start) {
      hit.square = {x + world_.min.x, y + world_.min.y};
      hit.material = m;
      return hit;
    }
  }
  return std::nullopt;
}

// Every square is read (the landscape's answer lists every material, so no early exit); a byte
// per material, as a bitset's shifts would cost more than the read.
std::vector<Material> BitmapWorld::overlaps(const Box64& box) const {
  std::array<std::uint8_t, kMaterialCount> found{};
  const std::int64_t x0 = std::max(box.min.x - world_.min.x, std::int64_t{0});
  const std::int64_t x1 = std::min(box.max.x - world_.min.x, width_);
  const std::int64_t y0 = std::max(box.min.y - world_.min.y, std::int64_t{0});
  const std::int64_t y1 = std::min(box.max.y - world_.min.y, height_);
  for (std::int64_t y = y0; y < y1; ++y) {
    const std::uint8_t* line = cells_.data() + y * width_;
    for (std::int64_t x = x0; x < x1; ++x) found[line[x]] = 1;
  }
  std::vector<Material> out;
  for (std::size_t m = 1; m < kMaterialCount; ++m)
    if (found[m] != 0) out.push_back(static_cast<Material>(m));
  return out;
}

}  // namespace edgeland::bench
