#pragma once
// The PNG picture of `replay --png` and `demo`: landscape_picture.hpp under its first names.
#include "landscape_picture.hpp"

namespace edgeland::cli {

using PngError = PictureError;
using PngOptions = PictureOptions;

}  // namespace edgeland::cli
