// The command line's and markup's outline and shadow values
// (text_effect_style.hpp).
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/text_effect_style.hpp"

namespace curvetext {

namespace {

std::vector<std::string_view> fields(std::string_view text, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(separator, start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view f = text.substr(start, end - start);
    while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
    while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
    // Spaces run together in markup's values.
    if (!f.empty() || separator != ' ') out.push_back(f);
    start = end + 1;
  }
  return out;
}

double number(const char* what, std::string_view f, bool non_negative) {
  double v = 0.0;
  if (!f.empty() && f.front() == '+') f.remove_prefix(1);
  if (f.size() > 2 && f.substr(f.size() - 2) == "px") f.remove_suffix(2);
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc{} || end != f.data() + f.size() || !std::isfinite(v))
    throw Error(ErrorCode::InvalidArgument,
                std::string(what) + " must be a finite number, got '" + std::string(f) + "'");
  if (non_negative && v < 0.0)
    throw Error(ErrorCode::InvalidArgument, std::string(what) + " must not be negative, got " + std::string(f));
  return v;
}

void expect_fields(const std::vector<std::string_view>& f, std::size_t n, const char* form) {
  if (f.size() != n)
    throw Error(ErrorCode::InvalidArgument, std::string("expected ") + form + ", got " + std::to_string(f.size()) +
                                                " field" + (f.size() == 1 ? "" : "s"));
}

}  // namespace

void parse_outline(std::string_view text, char separator, TextEffects& effects) {
  const std::vector<std::string_view> f = fields(text, separator);
  expect_fields(f, 2, separator == ',' ? "W,COLOR" : "'W COLOR'");
  effects.outline_width = number("the outline width", f[0], true);
  effects.outline_color = parse_color(f[1]);
}

TextShadow parse_shadow(std::string_view text, char separator) {
  const std::vector<std::string_view> f = fields(text, separator);
  expect_fields(f, 4, separator == ',' ? "DX,DY,BLUR,COLOR" : "'DX DY BLUR COLOR'");
  return TextShadow{number("the shadow's x offset", f[0], false), number("the shadow's y offset", f[1], false),
                    number("the shadow's blur radius", f[2], true), parse_color(f[3])};
}

}  // namespace curvetext
