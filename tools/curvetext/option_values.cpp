#include "option_values.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"

namespace curvetext::cli {

AntiAliasing parse_antialiasing(std::string_view text) {
  if (text == "none") return AntiAliasing::None;
  if (text == "curves") return AntiAliasing::Curves;
  if (text == "full") return AntiAliasing::Full;
  if (text == "vbaa") return AntiAliasing::Vbaa;
  if (text == "msaa") return AntiAliasing::Msaa;
  if (text == "auto") return AntiAliasing::Auto;
  throw Error(ErrorCode::InvalidArgument,
              "unknown antialiasing mode '" + std::string(text) + "' (use none, curves, full, vbaa, msaa or auto)");
}

CurveMode parse_curve_mode(std::string_view text) {
  if (text == "exact") return CurveMode::Exact;
  if (text == "paper") return CurveMode::Paper;
  throw Error(ErrorCode::InvalidArgument, "unknown curve mode '" + std::string(text) + "' (use exact or paper)");
}

Blending parse_blending(std::string_view text) {
  if (text == "srgb") return Blending::Srgb;
  if (text == "linear") return Blending::Linear;
  throw Error(ErrorCode::InvalidArgument, "unknown blending '" + std::string(text) + "' (use srgb or linear)");
}

float parse_vbaa_filter(std::string_view text) {
  if (text == "box") return 0.0f;
  if (text == "paper") return tolerance::kVbaaPaperRing;
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v) || v < 0.0 || v > 1.0)
    throw Error(ErrorCode::InvalidArgument,
                "unknown vbaa filter '" + std::string(text) + "' (use box, paper, or a ring weight from 0 to 1)");
  return static_cast<float>(v);
}

void check_gamma(double gamma, std::string_view option) {
  if (!std::isfinite(gamma) || gamma < tolerance::kMinCoverageGamma || gamma > tolerance::kMaxCoverageGamma) {
    char buf[160];
    std::snprintf(buf, sizeof buf, " must be a number from %g to %g, got %g", tolerance::kMinCoverageGamma,
                  tolerance::kMaxCoverageGamma, gamma);
    throw Error(ErrorCode::InvalidArgument, std::string(option) + buf);
  }
}

}  // namespace curvetext::cli
