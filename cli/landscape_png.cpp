#include "landscape_png.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <memory>

#include "material_palette.hpp"

namespace edgeland::cli {
namespace {

struct SurfaceCloser {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextCloser {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

// World coordinates to pixels: scaled, and flipped so that +y points up in the picture.
struct Frame {
  Box64 world;
  double scale = 1;
  int width = 1, height = 1;

  double x(std::int64_t wx) const { return static_cast<double>(wx - world.min.x) * scale; }
  double y(std::int64_t wy) const { return static_cast<double>(world.max.y - wy) * scale; }
};

Frame frame_for(const Box64& world, const PngOptions& options) {
  const double w = static_cast<double>(world.max.x - world.min.x);
  const double h = static_cast<double>(world.max.y - world.min.y);
  const double long_side = std::max(w, h);
  const double pixels = std::clamp(long_side, static_cast<double>(options.min_long_side),
                                   static_cast<double>(options.max_long_side));
  Frame f{world, pixels / long_side};
  f.width = std::max(1, static_cast<int>(w * f.scale + 0.5));
  f.height = std::max(1, static_cast<int>(h * f.scale + 0.5));
  return f;
}

void set_colour(cairo_t* cr, Rgb c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

// Every material's polygons, one list per material.
std::array<std::vector<const Polygon*>, kMaterialCount> polygons_by_material(const Landscape& l) {
  std::array<std::vector<const Polygon*>, kMaterialCount> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out[v.material.value()].push_back(v.polygon);
    return true;
  });
  return out;
}

// One path per material, filled by the non-zero rule: the pieces of a material cut at cell
// lines share those edges and are covered as one region, so no seam shows between them.
void draw_material(cairo_t* cr, const Frame& f, const std::vector<const Polygon*>& polygons,
                   Rgb c) {
  if (polygons.empty()) return;
  cairo_new_path(cr);
  for (const Polygon* p : polygons) {
    cairo_move_to(cr, f.x(p->front().x), f.y(p->front().y));
    for (const Point64& v : *p) cairo_line_to(cr, f.x(v.x), f.y(v.y));
    cairo_close_path(cr);
  }
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  set_colour(cr, c);
  cairo_fill(cr);
}

void draw_cells(cairo_t* cr, const Frame& f, const Landscape& landscape) {
  std::vector<Box64> cells;
  landscape.cells_in(landscape.world(), [&](const CellView& c) {
    cells.push_back(c.box);
    return true;
  });
  cairo_new_path(cr);
  for (const Box64& b : cells) {
    cairo_rectangle(cr, f.x(b.min.x), f.y(b.max.y), f.x(b.max.x) - f.x(b.min.x),
                    f.y(b.min.y) - f.y(b.max.y));
  }
  cairo_set_source_rgba(cr, 1, 1, 1, 0.35);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
}

void require_ok(cairo_status_t status, const std::string& path) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw PngError("cannot write PNG '" + path + "': " + cairo_status_to_string(status));
  }
}

}  // namespace

void write_landscape_png(const Landscape& landscape, const std::string& path,
                         const PngOptions& options) {
  const Frame f = frame_for(landscape.world(), options);
  const std::unique_ptr<cairo_surface_t, SurfaceCloser> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, f.width, f.height));
  require_ok(cairo_surface_status(surface.get()), path);
  const std::unique_ptr<cairo_t, ContextCloser> cr(cairo_create(surface.get()));
  set_colour(cr.get(), material_colour(kEmpty));
  cairo_paint(cr.get());
  const auto by_material = polygons_by_material(landscape);
  for (std::size_t m = 1; m < kMaterialCount; ++m) {
    const auto material = static_cast<Material>(m);
    draw_material(cr.get(), f, by_material[m], material_colour(material));
  }
  if (options.cells) draw_cells(cr.get(), f, landscape);
  require_ok(cairo_status(cr.get()), path);
  cairo_surface_flush(surface.get());
  require_ok(cairo_surface_write_to_png(surface.get(), path.c_str()), path);
}

}  // namespace edgeland::cli
