// Colour parsing for the CLI and API: CSS-like hex forms and a few names.
#include "curvetext/color.hpp"

#include <string>

#include "curvetext/error.hpp"

namespace curvetext {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

[[noreturn]] void bad(std::string_view text, const char* why) {
  throw Error(ErrorCode::InvalidArgument,
              "invalid color '" + std::string(text) + "': " + why +
                  " (use #rgb, #rrggbb, #rrggbbaa, black, white, red, green, blue or transparent)");
}

}  // namespace

Color parse_color(std::string_view text) {
  if (text == "black") return {0, 0, 0, 1};
  if (text == "white") return {1, 1, 1, 1};
  if (text == "red") return {1, 0, 0, 1};
  if (text == "green") return {0, 1, 0, 1};
  if (text == "blue") return {0, 0, 1, 1};
  if (text == "transparent") return {0, 0, 0, 0};
  if (text.empty() || text[0] != '#') bad(text, "unknown color name");
  const std::string_view hex = text.substr(1);
  if (hex.size() != 3 && hex.size() != 6 && hex.size() != 8) bad(text, "wrong number of hex digits");
  int v[8] = {};
  for (std::size_t i = 0; i < hex.size(); ++i) {
    v[i] = hex_digit(hex[i]);
    if (v[i] < 0) bad(text, "not a hex digit");
  }
  Color c;
  if (hex.size() == 3) {
    // #rgb means #rrggbb: each digit repeated, i.e. times 17.
    c.r = static_cast<float>(v[0] * 17) / 255.0f;
    c.g = static_cast<float>(v[1] * 17) / 255.0f;
    c.b = static_cast<float>(v[2] * 17) / 255.0f;
    return c;
  }
  c.r = static_cast<float>(v[0] * 16 + v[1]) / 255.0f;
  c.g = static_cast<float>(v[2] * 16 + v[3]) / 255.0f;
  c.b = static_cast<float>(v[4] * 16 + v[5]) / 255.0f;
  c.a = hex.size() == 8 ? static_cast<float>(v[6] * 16 + v[7]) / 255.0f : 1.0f;
  return c;
}

}  // namespace curvetext
