// The values of the CLI's drawing options (--aa, --curve, --blend,
// --vbaa-filter, --gamma), as the user types them. Each parser throws
// Error(InvalidArgument) naming the value and what is accepted (exit status
// 1, as for the library's own errors). The benchmarks' mode lists use them
// too.
#pragma once

#include <string_view>

#include "curvetext/renderer.hpp"

namespace curvetext::cli {

// "none" | "curves" | "full" | "vbaa" | "msaa" | "auto".
AntiAliasing parse_antialiasing(std::string_view text);
// "exact" | "paper".
CurveMode parse_curve_mode(std::string_view text);
// "srgb" | "linear".
Blending parse_blending(std::string_view text);
// vbaa's filter ring: "box" (0), "paper" (tolerance::kVbaaPaperRing) or a
// ring weight from 0 to 1.
float parse_vbaa_filter(std::string_view text);
// Coverage gamma: finite, within [tolerance::kMinCoverageGamma,
// kMaxCoverageGamma]; the message names `option`.
void check_gamma(double gamma, std::string_view option);

}  // namespace curvetext::cli
