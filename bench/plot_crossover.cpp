// plot_crossover: draws the crossover plot of bench/README.md ("Landscape") with cairo: the
// median time of one carve against the circle's radius, log-log, for the landscape and the
// bitmap, with the crossover radius marked.
//
//   plot_crossover DATA.tsv OUT.png [CROSSOVER_RADIUS]
//
// DATA.tsv (run_landscape.sh writes it): one line per radius, "radius landscape_us bitmap_us".
// Without a crossover radius the plot says that the curves do not cross in the range.
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Row {
  double radius, landscape_us, bitmap_us;
};

constexpr double kWidth = 900, kHeight = 600;
constexpr double kLeft = 90, kRight = 30, kTop = 50, kBottom = 70;

struct Axes {
  double x0, x1, y0, y1;  // log10 of the ranges
  double x(double radius) const { return kLeft + (std::log10(radius) - x0) / (x1 - x0) * (kWidth - kLeft - kRight); }
  double y(double us) const { return kHeight - kBottom - (std::log10(us) - y0) / (y1 - y0) * (kHeight - kTop - kBottom); }
};

std::vector<Row> read_rows(const char* path) {
  std::vector<Row> rows;
  std::ifstream in(path);
  Row r{};
  while (in >> r.radius >> r.landscape_us >> r.bitmap_us) rows.push_back(r);
  return rows;
}

Axes axes_for(const std::vector<Row>& rows) {
  double lo = 1e300, hi = 0;
  for (const Row& r : rows) {
    lo = std::min({lo, r.landscape_us, r.bitmap_us});
    hi = std::max({hi, r.landscape_us, r.bitmap_us});
  }
  return {std::log10(rows.front().radius) - 0.1, std::log10(rows.back().radius) + 0.1,
          std::floor(std::log10(lo)), std::ceil(std::log10(hi))};
}

void text(cairo_t* cr, double x, double y, const std::string& s, double align) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align * e.width, y);
  cairo_show_text(cr, s.c_str());
}

std::string us_label(double us) {
  char buf[32];
  if (us >= 1000) std::snprintf(buf, sizeof buf, "%g ms", us / 1000);
  else std::snprintf(buf, sizeof buf, "%g us", us);
  return buf;
}

void draw_grid(cairo_t* cr, const Axes& a, const std::vector<Row>& rows) {
  cairo_set_font_size(cr, 13);
  cairo_set_line_width(cr, 1);
  for (double d = a.y0; d <= a.y1 + 1e-9; d += 1) {  // a line per decade of time
    const double y = a.y(std::pow(10, d));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kWidth - kRight, y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, kLeft - 8, y + 4, us_label(std::pow(10, d)), 1.0);
  }
  for (const Row& r : rows) {  // a line per measured radius
    const double x = a.x(r.radius);
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, x, kTop);
    cairo_line_to(cr, x, kHeight - kBottom);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, x, kHeight - kBottom + 18, std::to_string(static_cast<long>(r.radius)), 0.5);
  }
  text(cr, (kLeft + kWidth - kRight) / 2, kHeight - 20, "circle radius (units; 16-512 vertices)", 0.5);
  cairo_save(cr);
  cairo_translate(cr, 22, (kTop + kHeight - kBottom) / 2);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, 0, 0, "median time of one carve", 0.5);
  cairo_restore(cr);
}

void draw_curve(cairo_t* cr, const Axes& a, const std::vector<Row>& rows, bool landscape) {
  if (landscape) cairo_set_source_rgb(cr, 0.12, 0.35, 0.75);
  else cairo_set_source_rgb(cr, 0.85, 0.35, 0.1);
  cairo_set_line_width(cr, 2.5);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double x = a.x(rows[i].radius), y = a.y(landscape ? rows[i].landscape_us : rows[i].bitmap_us);
    if (i == 0) cairo_move_to(cr, x, y);
    else cairo_line_to(cr, x, y);
  }
  cairo_stroke(cr);
  for (const Row& r : rows) {
    cairo_arc(cr, a.x(r.radius), a.y(landscape ? r.landscape_us : r.bitmap_us), 4, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

void draw_legend_and_title(cairo_t* cr, double crossover) {
  cairo_set_font_size(cr, 16);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, kWidth / 2, 30, "Carving a circle into a 16384^2 cave terrain: polygons vs pixels", 0.5);
  cairo_set_font_size(cr, 14);
  const char* names[2] = {"landscape (quadtree)", "bitmap (1 byte per square)"};
  for (int i = 0; i < 2; ++i) {
    if (i == 0) cairo_set_source_rgb(cr, 0.12, 0.35, 0.75);
    else cairo_set_source_rgb(cr, 0.85, 0.35, 0.1);
    cairo_rectangle(cr, kLeft + 20, kTop + 15 + 22 * i, 18, 10);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, kLeft + 45, kTop + 25 + 22 * i, names[i], 0.0);
  }
  if (crossover <= 0) text(cr, kLeft + 20, kTop + 25 + 44, "no crossover in this range", 0.0);
}

void draw_crossover(cairo_t* cr, const Axes& a, double radius) {
  const double x = a.x(radius);
  const double dash[] = {6, 4};
  cairo_set_source_rgb(cr, 0.1, 0.55, 0.2);
  cairo_set_line_width(cr, 2);
  cairo_set_dash(cr, dash, 2, 0);
  cairo_move_to(cr, x, kTop);
  cairo_line_to(cr, x, kHeight - kBottom);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  char label[64];
  std::snprintf(label, sizeof label, "crossover ~ r = %.0f", radius);
  text(cr, x - 6, kTop + 80, label, 1.0);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: plot_crossover DATA.tsv OUT.png [CROSSOVER_RADIUS]\n");
    return 2;
  }
  const std::vector<Row> rows = read_rows(argv[1]);
  if (rows.size() < 2) {
    std::fprintf(stderr, "plot_crossover: %s: fewer than two rows\n", argv[1]);
    return 2;
  }
  const double crossover = argc > 3 ? std::atof(argv[3]) : 0;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(kWidth), static_cast<int>(kHeight));
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const Axes a = axes_for(rows);
  draw_grid(cr, a, rows);
  draw_curve(cr, a, rows, false);
  draw_curve(cr, a, rows, true);
  if (crossover > 0) draw_crossover(cr, a, crossover);
  draw_legend_and_title(cr, crossover);
  const cairo_status_t status = cairo_surface_write_to_png(surface, argv[2]);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::fprintf(stderr, "plot_crossover: cannot write %s: %s\n", argv[2], cairo_status_to_string(status));
    return 1;
  }
  return 0;
}
