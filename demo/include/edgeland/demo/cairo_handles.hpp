#pragma once
// Owning handles of cairo's surfaces and drawing contexts, destroyed when they go out of scope:
// the command's pictures (cli/landscape_picture.cpp) and the desktop demo's overlay text and
// screenshot (play/desktop/src/picture.cpp). Header-only: edgeland_demo does not link cairo
// (the browser build has none); a target that includes this links cairo itself.
#include <cairo.h>

#include <memory>

namespace edgeland::demo {

struct CairoSurfaceCloser {
  void operator()(cairo_surface_t* s) const noexcept { cairo_surface_destroy(s); }
};
struct CairoContextCloser {
  void operator()(cairo_t* c) const noexcept { cairo_destroy(c); }
};
using CairoSurface = std::unique_ptr<cairo_surface_t, CairoSurfaceCloser>;
using CairoContext = std::unique_ptr<cairo_t, CairoContextCloser>;

}  // namespace edgeland::demo
