#include "style_options.hpp"

#include <algorithm>
#include <cmath>

#include "curvetext/error.hpp"
#include "option_values.hpp"

namespace curvetext::cli {

std::vector<double> parse_numbers(const std::string& option, const std::string& text, std::size_t lo, std::size_t hi) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    values.push_back(
        parse_number(option, text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() < lo || values.size() > hi)
    throw UsageError{option + " takes " +
                     (lo == hi ? std::to_string(lo) : std::to_string(lo) + " or " + std::to_string(hi)) +
                     " comma-separated numbers, got " + std::to_string(values.size())};
  for (double v : values)
    if (!std::isfinite(v))
      throw Error(ErrorCode::InvalidArgument, option + " needs finite numbers, got '" + text + "'");
  return values;
}

bool StyleCli::parse_transform(Args& args) {
  const std::string o = args.option();
  Transform step;
  if (o == "--rotate") {
    step = Transform::rotation(parse_numbers(o, args.value(), 1, 1)[0]);
  } else if (o == "--scale" && scale_is_transform_) {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    step = Transform::scale(v[0], v.size() > 1 ? v[1] : v[0]);
  } else if (o == "--skew") {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    if (std::abs(v[0]) >= 89.0 || (v.size() > 1 && std::abs(v[1]) >= 89.0))
      throw Error(ErrorCode::InvalidArgument, "--skew angles must be within (-89, 89) degrees");
    step = Transform::skew(v[0], v.size() > 1 ? v[1] : 0.0);
  } else if (o == "--perspective") {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    if (std::abs(v[0]) >= 90.0)
      throw Error(ErrorCode::InvalidArgument, "--perspective angle must be within (-90, 90) degrees");
    if (v.size() > 1 && !(v[1] > 0.0))
      throw Error(ErrorCode::InvalidArgument, "--perspective distance must be positive");
    // The default distance depends on the image size, known only later.
    if (v.size() == 1) {
      if (!transform_.is_identity() || perspective_pending_)
        throw UsageError{"--perspective without a distance must come first (or give DEG,DIST)"};
      perspective_pending_ = true;
      perspective_degrees_ = v[0];
      return true;
    }
    step = Transform::perspective(v[0], v[1]);
  } else if (o == "--transform") {
    const auto v = parse_numbers(o, args.value(), 6, 9);
    if (v.size() == 6)
      step = Transform{{v[0], v[1], v[2], v[3], v[4], v[5], 0, 0, 1}};
    else
      step = Transform{{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]}};
  } else {
    return false;
  }
  step.validate();
  transform_ = step * transform_;
  return true;
}

bool StyleCli::parse(Args& args, ImageStyle& style) {
  const std::string a = args.option();
  if (!parse_drawing(args, style)) return false;
  if (a != "--bg" && raster_option_.empty()) raster_option_ = a;
  return true;
}

bool StyleCli::parse_drawing(Args& args, ImageStyle& style) {
  if (parse_transform(args)) return true;
  const std::string& a = args.option();
  if (a == "--aa")
    style.antialiasing = parse_antialiasing(args.value());
  else if (a == "--curve")
    style.curve_mode = parse_curve_mode(args.value());
  else if (a == "--bg")
    style.background = parse_color(args.value());
  else if (a == "--blend")
    style.blending = parse_blending(args.value());
  else if (a == "--gamma") {
    style.gamma = static_cast<float>(parse_number(a, args.value()));
    check_gamma(style.gamma, "--gamma");
  } else if (a == "--debug")
    style.debug = true;
  else if (a == "--vbaa-filter")
    style.vbaa_ring = parse_vbaa_filter(args.value());
  else
    return false;
  return true;
}

Transform StyleCli::transform(double width, double height) const {
  if (!perspective_pending_) return transform_;
  // Seen from twice the untransformed image's larger side, then the rest.
  return transform_ * Transform::perspective(perspective_degrees_, 2.0 * std::max(width, height));
}

}  // namespace curvetext::cli
