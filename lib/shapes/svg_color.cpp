// CSS colours (CSS Color 4's legacy and modern syntaxes of rgb() and hsl(),
// hex forms, the named colours of CSS Color 3 / SVG 1.1).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "svg_css.hpp"

namespace curvetext::svg {

namespace {

struct Named {
  const char* name;
  std::uint32_t rgb;
};

// CSS Color 3 section 4.3 (the same list as SVG 1.1 section 4.4).
constexpr Named kNamed[] = {
    {"aliceblue", 0xf0f8ff},
    {"antiquewhite", 0xfaebd7},
    {"aqua", 0x00ffff},
    {"aquamarine", 0x7fffd4},
    {"azure", 0xf0ffff},
    {"beige", 0xf5f5dc},
    {"bisque", 0xffe4c4},
    {"black", 0x000000},
    {"blanchedalmond", 0xffebcd},
    {"blue", 0x0000ff},
    {"blueviolet", 0x8a2be2},
    {"brown", 0xa52a2a},
    {"burlywood", 0xdeb887},
    {"cadetblue", 0x5f9ea0},
    {"chartreuse", 0x7fff00},
    {"chocolate", 0xd2691e},
    {"coral", 0xff7f50},
    {"cornflowerblue", 0x6495ed},
    {"cornsilk", 0xfff8dc},
    {"crimson", 0xdc143c},
    {"cyan", 0x00ffff},
    {"darkblue", 0x00008b},
    {"darkcyan", 0x008b8b},
    {"darkgoldenrod", 0xb8860b},
    {"darkgray", 0xa9a9a9},
    {"darkgreen", 0x006400},
    {"darkgrey", 0xa9a9a9},
    {"darkkhaki", 0xbdb76b},
    {"darkmagenta", 0x8b008b},
    {"darkolivegreen", 0x556b2f},
    {"darkorange", 0xff8c00},
    {"darkorchid", 0x9932cc},
    {"darkred", 0x8b0000},
    {"darksalmon", 0xe9967a},
    {"darkseagreen", 0x8fbc8f},
    {"darkslateblue", 0x483d8b},
    {"darkslategray", 0x2f4f4f},
    {"darkslategrey", 0x2f4f4f},
    {"darkturquoise", 0x00ced1},
    {"darkviolet", 0x9400d3},
    {"deeppink", 0xff1493},
    {"deepskyblue", 0x00bfff},
    {"dimgray", 0x696969},
    {"dimgrey", 0x696969},
    {"dodgerblue", 0x1e90ff},
    {"firebrick", 0xb22222},
    {"floralwhite", 0xfffaf0},
    {"forestgreen", 0x228b22},
    {"fuchsia", 0xff00ff},
    {"gainsboro", 0xdcdcdc},
    {"ghostwhite", 0xf8f8ff},
    {"gold", 0xffd700},
    {"goldenrod", 0xdaa520},
    {"gray", 0x808080},
    {"grey", 0x808080},
    {"green", 0x008000},
    {"greenyellow", 0xadff2f},
    {"honeydew", 0xf0fff0},
    {"hotpink", 0xff69b4},
    {"indianred", 0xcd5c5c},
    {"indigo", 0x4b0082},
    {"ivory", 0xfffff0},
    {"khaki", 0xf0e68c},
    {"lavender", 0xe6e6fa},
    {"lavenderblush", 0xfff0f5},
    {"lawngreen", 0x7cfc00},
    {"lemonchiffon", 0xfffacd},
    {"lightblue", 0xadd8e6},
    {"lightcoral", 0xf08080},
    {"lightcyan", 0xe0ffff},
    {"lightgoldenrodyellow", 0xfafad2},
    {"lightgray", 0xd3d3d3},
    {"lightgreen", 0x90ee90},
    {"lightgrey", 0xd3d3d3},
    {"lightpink", 0xffb6c1},
    {"lightsalmon", 0xffa07a},
    {"lightseagreen", 0x20b2aa},
    {"lightskyblue", 0x87cefa},
    {"lightslategray", 0x778899},
    {"lightslategrey", 0x778899},
    {"lightsteelblue", 0xb0c4de},
    {"lightyellow", 0xffffe0},
    {"lime", 0x00ff00},
    {"limegreen", 0x32cd32},
    {"linen", 0xfaf0e6},
    {"magenta", 0xff00ff},
    {"maroon", 0x800000},
    {"mediumaquamarine", 0x66cdaa},
    {"mediumblue", 0x0000cd},
    {"mediumorchid", 0xba55d3},
    {"mediumpurple", 0x9370db},
    {"mediumseagreen", 0x3cb371},
    {"mediumslateblue", 0x7b68ee},
    {"mediumspringgreen", 0x00fa9a},
    {"mediumturquoise", 0x48d1cc},
    {"mediumvioletred", 0xc71585},
    {"midnightblue", 0x191970},
    {"mintcream", 0xf5fffa},
    {"mistyrose", 0xffe4e1},
    {"moccasin", 0xffe4b5},
    {"navajowhite", 0xffdead},
    {"navy", 0x000080},
    {"oldlace", 0xfdf5e6},
    {"olive", 0x808000},
    {"olivedrab", 0x6b8e23},
    {"orange", 0xffa500},
    {"orangered", 0xff4500},
    {"orchid", 0xda70d6},
    {"palegoldenrod", 0xeee8aa},
    {"palegreen", 0x98fb98},
    {"paleturquoise", 0xafeeee},
    {"palevioletred", 0xdb7093},
    {"papayawhip", 0xffefd5},
    {"peachpuff", 0xffdab9},
    {"peru", 0xcd853f},
    {"pink", 0xffc0cb},
    {"plum", 0xdda0dd},
    {"powderblue", 0xb0e0e6},
    {"purple", 0x800080},
    {"rebeccapurple", 0x663399},
    {"red", 0xff0000},
    {"rosybrown", 0xbc8f8f},
    {"royalblue", 0x4169e1},
    {"saddlebrown", 0x8b4513},
    {"salmon", 0xfa8072},
    {"sandybrown", 0xf4a460},
    {"seagreen", 0x2e8b57},
    {"seashell", 0xfff5ee},
    {"sienna", 0xa0522d},
    {"silver", 0xc0c0c0},
    {"skyblue", 0x87ceeb},
    {"slateblue", 0x6a5acd},
    {"slategray", 0x708090},
    {"slategrey", 0x708090},
    {"snow", 0xfffafa},
    {"springgreen", 0x00ff7f},
    {"steelblue", 0x4682b4},
    {"tan", 0xd2b48c},
    {"teal", 0x008080},
    {"thistle", 0xd8bfd8},
    {"tomato", 0xff6347},
    {"turquoise", 0x40e0d0},
    {"violet", 0xee82ee},
    {"wheat", 0xf5deb3},
    {"white", 0xffffff},
    {"whitesmoke", 0xf5f5f5},
    {"yellow", 0xffff00},
    {"yellowgreen", 0x9acd32},
};

Color from_rgb(std::uint32_t rgb, float alpha = 1.0f) {
  return {static_cast<float>((rgb >> 16) & 0xff) / 255.0f, static_cast<float>((rgb >> 8) & 0xff) / 255.0f,
          static_cast<float>(rgb & 0xff) / 255.0f, alpha};
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::optional<Color> hex_color(std::string_view h) {
  int d[8] = {};
  if (h.size() > 8) return std::nullopt;  // (#rrggbbaa is the longest form)
  for (std::size_t i = 0; i < h.size(); ++i)
    if ((d[i] = hex_digit(h[i])) < 0) return std::nullopt;
  auto pair = [&](int i) { return static_cast<float>(d[i] * 16 + d[i + 1]) / 255.0f; };
  auto single = [&](int i) { return static_cast<float>(d[i] * 17) / 255.0f; };
  switch (h.size()) {
    case 3:
      return Color{single(0), single(1), single(2), 1.0f};
    case 4:
      return Color{single(0), single(1), single(2), single(3)};
    case 6:
      return Color{pair(0), pair(2), pair(4), 1.0f};
    case 8:
      return Color{pair(0), pair(2), pair(4), pair(6)};
    default:
      return std::nullopt;
  }
}

// A number with an optional '%'; nullopt when it is not one.
std::optional<std::pair<double, bool>> number_or_percent(std::string_view s) {
  std::string t = trim(s);
  const bool percent = !t.empty() && t.back() == '%';
  if (percent) t.pop_back();
  if (!t.empty() && t.front() == '+') t.erase(0, 1);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return std::pair{v, percent};
}

// The arguments of rgb()/hsl(): three values and an optional alpha, split by
// commas or by spaces with "/ alpha".
std::optional<std::vector<std::string>> arguments(std::string_view inner) {
  std::vector<std::string> out;
  std::string s(inner);
  for (char& c : s)
    if (c == ',' || c == '/' || c == '\t' || c == '\n' || c == '\r') c = ' ';
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && s[i] == ' ') ++i;
    const std::size_t j = s.find(' ', i);
    if (i < s.size()) out.push_back(s.substr(i, j == std::string::npos ? std::string::npos : j - i));
    i = j == std::string::npos ? s.size() : j;
  }
  if (out.size() != 3 && out.size() != 4) return std::nullopt;
  return out;
}

std::optional<float> alpha_argument(const std::vector<std::string>& args) {
  if (args.size() < 4) return 1.0f;
  const auto a = number_or_percent(args[3]);
  if (!a) return std::nullopt;
  return static_cast<float>(std::clamp(a->second ? a->first / 100.0 : a->first, 0.0, 1.0));
}

std::optional<Color> rgb_function(std::string_view inner) {
  const auto args = arguments(inner);
  if (!args) return std::nullopt;
  float c[3];
  for (int i = 0; i < 3; ++i) {
    const auto v = number_or_percent((*args)[i]);
    if (!v) return std::nullopt;
    c[i] = static_cast<float>(std::clamp(v->second ? v->first / 100.0 : v->first / 255.0, 0.0, 1.0));
  }
  const auto a = alpha_argument(*args);
  if (!a) return std::nullopt;
  return Color{c[0], c[1], c[2], *a};
}

std::optional<Color> hsl_function(std::string_view inner) {
  const auto args = arguments(inner);
  if (!args) return std::nullopt;
  std::string hue = (*args)[0];
  if (hue.size() > 3 && hue.ends_with("deg")) hue.resize(hue.size() - 3);
  const auto h = number_or_percent(hue), s = number_or_percent((*args)[1]), l = number_or_percent((*args)[2]);
  const auto a = alpha_argument(*args);
  if (!h || h->second || !s || !l || !a) return std::nullopt;
  // CSS Color 4 section 7.1's hsl-to-rgb.
  const double hh = std::fmod(std::fmod(h->first, 360.0) + 360.0, 360.0);
  const double ss = std::clamp(s->first / 100.0, 0.0, 1.0), ll = std::clamp(l->first / 100.0, 0.0, 1.0);
  auto f = [&](double n) {
    const double k = std::fmod(n + hh / 30.0, 12.0);
    const double amount = ss * std::min(ll, 1.0 - ll);
    return static_cast<float>(ll - amount * std::max(-1.0, std::min({k - 3.0, 9.0 - k, 1.0})));
  };
  return Color{f(0), f(8), f(4), *a};
}

}  // namespace

std::optional<Color> parse_css_color(std::string_view text) {
  const std::string t = lower(trim(text));
  if (t.empty()) return std::nullopt;
  if (t[0] == '#') return hex_color(std::string_view(t).substr(1));
  if (t == "transparent") return Color{0, 0, 0, 0};
  const std::size_t open = t.find('(');
  if (open != std::string::npos) {
    if (t.back() != ')') return std::nullopt;
    const std::string name = trim(std::string_view(t).substr(0, open));
    const std::string_view inner = std::string_view(t).substr(open + 1, t.size() - open - 2);
    if (name == "rgb" || name == "rgba") return rgb_function(inner);
    if (name == "hsl" || name == "hsla") return hsl_function(inner);
    return std::nullopt;
  }
  for (const Named& n : kNamed)
    if (t == n.name) return from_rgb(n.rgb);
  return std::nullopt;
}

std::string trim(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return std::string(s);
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

}  // namespace curvetext::svg
