// plot_crossover: draws the crossover plot of bench/README.md ("Landscape") with cairo: the
// median time of one carve against the circle's radius, log-log, bitmap and landscape, for each
// terrain, with each terrain's crossover radius marked.
//
//   plot_crossover DATA.tsv OUT.png
//
// DATA.tsv (landscape_tables.py writes it), tab-separated:
//   names <terrain 0> <terrain 1> ...
//   <radius> <bitmap us> <landscape us> (a pair per terrain)    one line per radius
//   crossover <terrain index> <radius>                           0: none in the range
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Data {
  std::vector<std::string> terrains;
  std::vector<double> radii;
  std::vector<std::vector<double>> values;  // per radius: bitmap, landscape for each terrain
  std::vector<double> crossovers;           // per terrain, 0 = none
};

constexpr double kWidth = 900, kHeight = 600;
constexpr double kLeft = 90, kRight = 30, kTop = 50, kBottom = 70;

struct Axes {
  double x0, x1, y0, y1;  // log10 of the ranges
  double x(double radius) const {
    return kLeft + (std::log10(radius) - x0) / (x1 - x0) * (kWidth - kLeft - kRight);
  }
  double y(double us) const {
    return kHeight - kBottom - (std::log10(us) - y0) / (y1 - y0) * (kHeight - kTop - kBottom);
  }
};

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, '\t');) out.push_back(field);
  return out;
}

Data read_data(const char* path) {
  Data d;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split_tabs(line);
    if (f.empty()) continue;
    if (f[0] == "names") {
      d.terrains.assign(f.begin() + 1, f.end());
      d.crossovers.assign(d.terrains.size(), 0);
    } else if (f[0] == "crossover" && f.size() == 3) {
      d.crossovers.at(std::stoul(f[1])) = std::stod(f[2]);
    } else if (f.size() == 1 + 2 * d.terrains.size()) {
      d.radii.push_back(std::stod(f[0]));
      d.values.emplace_back();
      for (std::size_t i = 1; i < f.size(); ++i) d.values.back().push_back(std::stod(f[i]));
    }
  }
  return d;
}

Axes axes_for(const Data& d) {
  double lo = 1e300, hi = 0;
  for (const auto& row : d.values) {
    lo = std::min(lo, *std::min_element(row.begin(), row.end()));
    hi = std::max(hi, *std::max_element(row.begin(), row.end()));
  }
  return {std::log10(d.radii.front()) - 0.1, std::log10(d.radii.back()) + 0.1,
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
  if (us >= 1000)
    std::snprintf(buf, sizeof buf, "%g ms", us / 1000);
  else
    std::snprintf(buf, sizeof buf, "%g us", us);
  return buf;
}

// Colour by rival (blue landscape, orange bitmap), dash pattern by terrain.
void set_style(cairo_t* cr, bool landscape, std::size_t terrain) {
  if (landscape)
    cairo_set_source_rgb(cr, 0.12, 0.35, 0.75);
  else
    cairo_set_source_rgb(cr, 0.85, 0.35, 0.1);
  const double dash[] = {8, 5};
  cairo_set_dash(cr, dash, terrain == 0 ? 0 : 2, 0);
}

void draw_grid(cairo_t* cr, const Axes& a, const Data& d) {
  cairo_set_font_size(cr, 13);
  cairo_set_line_width(cr, 1);
  for (double e = a.y0; e <= a.y1 + 1e-9; e += 1) {  // a line per decade of time
    const double y = a.y(std::pow(10, e));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kWidth - kRight, y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, kLeft - 8, y + 4, us_label(std::pow(10, e)), 1.0);
  }
  for (double r : d.radii) {  // a line per measured radius
    const double x = a.x(r);
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, x, kTop);
    cairo_line_to(cr, x, kHeight - kBottom);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, x, kHeight - kBottom + 18, std::to_string(static_cast<long>(r)), 0.5);
  }
  text(cr, (kLeft + kWidth - kRight) / 2, kHeight - 20, "circle radius (units; 16-512 vertices)",
       0.5);
  cairo_save(cr);
  cairo_translate(cr, 22, (kTop + kHeight - kBottom) / 2);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, 0, 0, "median time of one carve", 0.5);
  cairo_restore(cr);
}

void draw_curve(cairo_t* cr, const Axes& a, const Data& d, std::size_t column) {
  const bool landscape = column % 2 == 1;
  set_style(cr, landscape, column / 2);
  cairo_set_line_width(cr, 2.5);
  for (std::size_t i = 0; i < d.radii.size(); ++i) {
    const double x = a.x(d.radii[i]), y = a.y(d.values[i][column]);
    if (i == 0)
      cairo_move_to(cr, x, y);
    else
      cairo_line_to(cr, x, y);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  for (std::size_t i = 0; i < d.radii.size(); ++i) {
    cairo_arc(cr, a.x(d.radii[i]), a.y(d.values[i][column]), 3.5, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

void draw_crossover(cairo_t* cr, const Axes& a, double radius, std::size_t terrain,
                    const std::string& name) {
  const double x = a.x(radius);
  const double dash[] = {3, 3};
  cairo_set_source_rgb(cr, 0.1, 0.55, 0.2);
  cairo_set_line_width(cr, 2);
  cairo_set_dash(cr, dash, 2, 0);
  cairo_move_to(cr, x, kTop);
  cairo_line_to(cr, x, kHeight - kBottom);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  char label[96];
  std::snprintf(label, sizeof label, "crossover, %s: r ~ %.0f", name.c_str(), radius);
  cairo_set_font_size(cr, 13);
  text(cr, x - 6, kHeight - kBottom - 12 - 18 * static_cast<double>(terrain), label, 1.0);
}

void draw_legend_and_title(cairo_t* cr, const Data& d) {
  cairo_set_font_size(cr, 16);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, kWidth / 2, 30, "Carving a circle into a 16384^2 world: polygons vs pixels", 0.5);
  cairo_set_font_size(cr, 13);
  double y = kTop + 20;
  for (std::size_t t = 0; t < d.terrains.size(); ++t) {
    for (bool landscape : {true, false}) {
      set_style(cr, landscape, t);
      cairo_set_line_width(cr, 2.5);
      cairo_move_to(cr, kLeft + 15, y - 4);
      cairo_line_to(cr, kLeft + 45, y - 4);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      cairo_set_source_rgb(cr, 0, 0, 0);
      std::string label =
          std::string(landscape ? "landscape (quadtree), " : "bitmap (1 byte per square), ") +
          d.terrains[t];
      if (landscape && d.crossovers[t] <= 0) label += ": no crossover in this range";
      text(cr, kLeft + 52, y, label, 0.0);
      y += 18;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: plot_crossover DATA.tsv OUT.png\n");
    return 2;
  }
  const Data d = read_data(argv[1]);
  if (d.radii.size() < 2) {
    std::fprintf(stderr, "plot_crossover: %s: fewer than two radii\n", argv[1]);
    return 2;
  }
  cairo_surface_t* surface = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, static_cast<int>(kWidth), static_cast<int>(kHeight));
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const Axes a = axes_for(d);
  draw_grid(cr, a, d);
  for (std::size_t column = 0; column < 2 * d.terrains.size(); ++column)
    draw_curve(cr, a, d, column);
  for (std::size_t t = 0; t < d.terrains.size(); ++t)
    if (d.crossovers[t] > 0) draw_crossover(cr, a, d.crossovers[t], t, d.terrains[t]);
  draw_legend_and_title(cr, d);
  const cairo_status_t status = cairo_surface_write_to_png(surface, argv[2]);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::fprintf(stderr, "plot_crossover: cannot write %s: %s\n", argv[2],
                 cairo_status_to_string(status));
    return 1;
  }
  return 0;
}
