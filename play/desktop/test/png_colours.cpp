// png_colours FILE.png: prints the picture's width, height and number of distinct colours, so
// a test can tell a drawn frame from a blank one without trusting the program that drew it.
#include <cairo.h>

#include <cstdint>
#include <cstdio>
#include <unordered_set>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: png_colours FILE.png\n");
    return 2;
  }
  cairo_surface_t* image = cairo_image_surface_create_from_png(argv[1]);
  if (cairo_surface_status(image) != CAIRO_STATUS_SUCCESS) {
    std::fprintf(stderr, "png_colours: cannot read %s\n", argv[1]);
    return 2;
  }
  const int width = cairo_image_surface_get_width(image);
  const int height = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  std::unordered_set<std::uint32_t> colours;
  for (int y = 0; y < height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
    for (int x = 0; x < width; ++x) colours.insert(row[x] & 0xffffffu);
  }
  std::printf("%d %d %zu\n", width, height, colours.size());
  cairo_surface_destroy(image);
  return 0;
}
