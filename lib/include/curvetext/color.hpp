// Colours: straight (not premultiplied) RGBA in [0,1].
#pragma once

#include <string_view>

#include "curvetext/export.hpp"

namespace curvetext {

struct Color {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
};

// "#rgb", "#rrggbb", "#rrggbbaa", or a name: black, white, red, green, blue,
// transparent. Kept in the library because shape documents (SVG fill, the
// JSON format's "color") are read with it, so callers can parse colours the
// same way. Throws Error(InvalidArgument).
CURVETEXT_API Color parse_color(std::string_view text);

}  // namespace curvetext
