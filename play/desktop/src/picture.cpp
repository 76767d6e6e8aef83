#include "picture.hpp"

#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <memory>

#include "edgeland/demo/cairo_handles.hpp"

namespace edgeland::play {
namespace {

using Surface = demo::CairoSurface;
using Context = demo::CairoContext;

constexpr double kFontSize = 13;
constexpr int kLineHeight = 17;

}  // namespace

SDL_Texture* text_texture(SDL_Renderer* renderer, const std::vector<std::string>& lines) {
  std::size_t longest = 1;
  for (const std::string& line : lines) longest = std::max(longest, line.size());
  const int width = static_cast<int>(longest) * 8 + 12;
  const int height = static_cast<int>(lines.size()) * kLineHeight + 8;
  const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  {
    const Context cr(cairo_create(surface.get()));
    cairo_set_source_rgba(cr.get(), 0, 0, 0, 0.6);
    cairo_paint(cr.get());
    cairo_select_font_face(cr.get(), "monospace", CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr.get(), kFontSize);
    cairo_set_source_rgb(cr.get(), 0.9, 0.92, 0.95);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      cairo_move_to(cr.get(), 6, 4 + kFontSize + static_cast<double>(i * kLineHeight));
      cairo_show_text(cr.get(), lines[i].c_str());
    }
  }
  cairo_surface_flush(surface.get());
  // cairo's ARGB32 is a native-endian 32-bit word, SDL's ARGB8888 the same.
  SDL_Texture* texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888,
                                           SDL_TEXTUREACCESS_STATIC, width, height);
  if (texture == nullptr) return nullptr;
  SDL_UpdateTexture(texture, nullptr, cairo_image_surface_get_data(surface.get()),
                    cairo_image_surface_get_stride(surface.get()));
  SDL_SetTextureBlendMode(texture, SDL_BLENDMODE_BLEND);
  return texture;
}

void release_text_caches() {
  cairo_debug_reset_static_data();
  FcFini();
}

void save_screenshot(SDL_Renderer* renderer, const std::string& path) {
  int width = 0, height = 0;
  if (SDL_GetRendererOutputSize(renderer, &width, &height) != 0) {
    throw PictureFailure(std::string("cannot read the window: ") + SDL_GetError());
  }
  const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  cairo_surface_flush(surface.get());
  if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_ARGB8888,
                           cairo_image_surface_get_data(surface.get()),
                           cairo_image_surface_get_stride(surface.get())) != 0) {
    throw PictureFailure(std::string("cannot read the window: ") + SDL_GetError());
  }
  cairo_surface_mark_dirty(surface.get());
  if (cairo_surface_write_to_png(surface.get(), path.c_str()) != CAIRO_STATUS_SUCCESS) {
    throw PictureFailure("cannot write '" + path + "'");
  }
}

}  // namespace edgeland::play
