// Colours: straight (not premultiplied) RGBA in [0,1].
#pragma once

#include <string_view>

namespace curvetext {

struct Color {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
};

// "#rgb", "#rrggbb", "#rrggbbaa", or a name: black, white, red, green, blue,
// transparent. Throws Error(InvalidArgument).
Color parse_color(std::string_view text);

}  // namespace curvetext
