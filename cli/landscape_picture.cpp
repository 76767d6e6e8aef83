#include "landscape_picture.hpp"

#include <cairo-svg.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>

#include "edgeland/demo/cairo_handles.hpp"

namespace edgeland::cli {
namespace {

using Surface = demo::CairoSurface;
using Context = demo::CairoContext;

constexpr int kLegendWidth = 200;  // pixels right of the world
constexpr int kLegendRow = 22;

// World coordinates to pixels: scaled, and flipped so that +y points up in the picture.
struct Frame {
  Box64 world;
  double scale = 1;
  int width = 1, height = 1;  // the world's part of the picture

  double x(std::int64_t wx) const { return static_cast<double>(wx - world.min.x) * scale; }
  double y(std::int64_t wy) const { return static_cast<double>(world.max.y - wy) * scale; }
};

Frame frame_for(const Box64& world, const PictureOptions& options) {
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

void set_colour(cairo_t* cr, demo::Rgb c, double alpha = 1) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

// Every material's polygons, one list per material.
std::array<std::vector<const Polygon*>, kMaterialCount> polygons_by_material(const Landscape& l) {
  std::array<std::vector<const Polygon*>, kMaterialCount> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out[v.material.value()].push_back(v.polygon.get());  // drawn while the landscape lives
    return true;
  });
  return out;
}

void trace(cairo_t* cr, const Frame& f, const std::vector<Point64>& path, bool closed) {
  if (path.empty()) return;
  cairo_move_to(cr, f.x(path.front().x), f.y(path.front().y));
  for (const Point64& v : path) cairo_line_to(cr, f.x(v.x), f.y(v.y));
  if (closed) cairo_close_path(cr);
}

// One path per material, filled by the non-zero rule: the pieces of a material cut at cell
// lines share those edges and are covered as one region, so no seam shows between them.
void draw_material(cairo_t* cr, const Frame& f, const std::vector<const Polygon*>& polygons,
                   demo::Rgb c) {
  if (polygons.empty()) return;
  cairo_new_path(cr);
  for (const Polygon* p : polygons) trace(cr, f, *p, true);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  set_colour(cr, c);
  cairo_fill(cr);
}

void draw_cells(cairo_t* cr, const Frame& f, const Landscape& landscape) {
  cairo_new_path(cr);
  landscape.cells_in(landscape.world(), [&](const CellView& c) {
    const Box64& b = c.box;
    cairo_rectangle(cr, f.x(b.min.x), f.y(b.max.y), f.x(b.max.x) - f.x(b.min.x),
                    f.y(b.min.y) - f.y(b.max.y));
    return true;
  });
  cairo_set_source_rgba(cr, 1, 1, 1, 0.35);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
}

void draw_layer(cairo_t* cr, const Frame& f, const PictureLayer& layer) {
  cairo_new_path(cr);
  for (const std::vector<Point64>& path : layer.paths) trace(cr, f, path, layer.closed);
  if (layer.fill) {
    set_colour(cr, layer.colour, layer.opacity / 4);
    cairo_fill_preserve(cr);
  }
  set_colour(cr, layer.colour, layer.opacity);
  cairo_set_line_width(cr, layer.line_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

void draw_world(cairo_t* cr, const Frame& f, const Landscape& landscape,
                const PictureOptions& options) {
  set_colour(cr, demo::material_colour(kEmpty));
  cairo_rectangle(cr, 0, 0, f.width, f.height);
  cairo_fill(cr);
  const auto by_material = polygons_by_material(landscape);
  for (std::size_t m = 1; m < kMaterialCount; ++m) {
    const auto material = static_cast<Material>(m);
    draw_material(cr, f, by_material[m], demo::material_colour(material));
  }
  if (options.cells) draw_cells(cr, f, landscape);
  for (const PictureLayer& layer : options.layers) draw_layer(cr, f, layer);
}

// --- the legend: one row per material present (swatch, number, name, share of the world's
// area), then one per layer (its line) ---------------------------------------------------------

int legend_rows(const Landscape& landscape, const PictureOptions& options) {
  int rows = 1 + static_cast<int>(options.layers.size()) + (options.cells ? 1 : 0);
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    rows += landscape.twice_area(static_cast<Material>(m)) != 0 ? 1 : 0;
  }
  return rows;
}

void legend_text(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_set_source_rgb(cr, 0.86, 0.87, 0.9);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

double legend_materials(cairo_t* cr, double x, double y, const Landscape& landscape) {
  const Box64& w = landscape.world();
  const double world_area =
      static_cast<double>(w.max.x - w.min.x) * static_cast<double>(w.max.y - w.min.y);
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    const auto material = static_cast<Material>(m);
    const Int128 twice = landscape.twice_area(material);
    if (twice == 0) continue;
    set_colour(cr, demo::material_colour(material));
    cairo_rectangle(cr, x, y - 12, 16, 14);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.5);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    char share[32];
    std::snprintf(share, sizeof share, "%.1f%%",
                  100.0 * static_cast<double>(twice) / 2.0 / world_area);
    legend_text(cr, x + 24, y, std::to_string(m) + " " + demo::material_name(material));
    legend_text(cr, x + 140, y, share);
    y += kLegendRow;
  }
  return y;
}

void legend_line(cairo_t* cr, double x, double y, demo::Rgb colour, double opacity, double width,
                 const std::string& label) {
  set_colour(cr, colour, opacity);
  cairo_set_line_width(cr, width);
  cairo_move_to(cr, x, y - 5);
  cairo_line_to(cr, x + 16, y - 5);
  cairo_stroke(cr);
  legend_text(cr, x + 24, y, label);
}

void draw_legend(cairo_t* cr, const Frame& f, const Landscape& landscape,
                 const PictureOptions& options, int height) {
  cairo_set_source_rgb(cr, 0.11, 0.12, 0.15);
  cairo_rectangle(cr, f.width, 0, kLegendWidth, height);
  cairo_fill(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 13);
  const double x = f.width + 14;
  legend_text(cr, x, 24, "material          area");
  double y = legend_materials(cr, x, 24 + kLegendRow, landscape);
  if (options.cells) {
    legend_line(cr, x, y, demo::Rgb{255, 255, 255}, 0.35, 1, "cell lines");
    y += kLegendRow;
  }
  for (const PictureLayer& layer : options.layers) {
    legend_line(cr, x, y, layer.colour, layer.opacity, layer.line_width, layer.label);
    y += kLegendRow;
  }
}

// The picture's size: the world, and the legend's column when asked for.
struct Canvas {
  int width, height;
};

Canvas canvas_for(const Frame& f, const Landscape& landscape, const PictureOptions& options) {
  if (!options.legend) return {f.width, f.height};
  return {f.width + kLegendWidth,
          std::max(f.height, 24 + kLegendRow * legend_rows(landscape, options) + 8)};
}

void draw_picture(cairo_t* cr, const Frame& f, const Canvas& canvas, const Landscape& landscape,
                  const PictureOptions& options) {
  set_colour(cr, demo::material_colour(kEmpty));
  cairo_paint(cr);
  draw_world(cr, f, landscape, options);
  if (options.legend) draw_legend(cr, f, landscape, options, canvas.height);
}

void require_ok(cairo_status_t status, const char* kind, const std::string& path) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw PictureError(std::string("cannot write ") + kind + " '" + path +
                       "': " + cairo_status_to_string(status));
  }
}

// The legend's text goes through fontconfig, which keeps its configuration and caches until the
// process ends; they are released after each picture with text, so that a leak checker sees a
// clean exit (fontconfig loads them again when asked).
void release_font_caches() {
  cairo_debug_reset_static_data();
  FcFini();
}

void draw_png(const Landscape& landscape, const std::string& path, const PictureOptions& options) {
  const Frame f = frame_for(landscape.world(), options);
  const Canvas canvas = canvas_for(f, landscape, options);
  const Surface surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, canvas.width, canvas.height));
  require_ok(cairo_surface_status(surface.get()), "PNG", path);
  const Context cr(cairo_create(surface.get()));
  draw_picture(cr.get(), f, canvas, landscape, options);
  require_ok(cairo_status(cr.get()), "PNG", path);
  cairo_surface_flush(surface.get());
  require_ok(cairo_surface_write_to_png(surface.get(), path.c_str()), "PNG", path);
}

void draw_svg(const Landscape& landscape, const std::string& path, const PictureOptions& options) {
  const Frame f = frame_for(landscape.world(), options);
  const Canvas canvas = canvas_for(f, landscape, options);
  const Surface surface(cairo_svg_surface_create(path.c_str(), canvas.width, canvas.height));
  require_ok(cairo_surface_status(surface.get()), "SVG", path);
  {
    const Context cr(cairo_create(surface.get()));
    draw_picture(cr.get(), f, canvas, landscape, options);
    require_ok(cairo_status(cr.get()), "SVG", path);
  }
  cairo_surface_finish(surface.get());  // writes the file
  require_ok(cairo_surface_status(surface.get()), "SVG", path);
}

}  // namespace

// The caches are released once every cairo object of the picture is gone (cairo asserts that).
void write_landscape_png(const Landscape& landscape, const std::string& path,
                         const PictureOptions& options) {
  draw_png(landscape, path, options);
  if (options.legend) release_font_caches();
}

void write_landscape_svg(const Landscape& landscape, const std::string& path,
                         const PictureOptions& options) {
  draw_svg(landscape, path, options);
  if (options.legend) release_font_caches();
}

}  // namespace edgeland::cli
