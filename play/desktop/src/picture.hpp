#pragma once
// Pixels in and out of SDL through cairo: the overlay's text as a texture, and the screenshot
// (SDL_RenderReadPixels) as a PNG file.
#include <SDL.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace edgeland::play {

class PictureFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Lines of text on a translucent dark panel, as a texture (the caller destroys it).
SDL_Texture* text_texture(SDL_Renderer* renderer, const std::vector<std::string>& lines);

// Releases cairo's and fontconfig's caches, which the text fills and which otherwise live until
// the process ends (a leak checker reports them): call once, at the end.
void release_text_caches();

// The renderer's current target as a PNG file. Throws PictureFailure.
void save_screenshot(SDL_Renderer* renderer, const std::string& path);

}  // namespace edgeland::play
