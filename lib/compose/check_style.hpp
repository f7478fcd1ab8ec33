// Private: checks of ImageStyle values shared by compose/'s image paths, made
// before anything is drawn.
#pragma once

namespace curvetext {

// Throws Error(InvalidArgument) "gamma must be a number from ... got ..."
// unless `gamma` is finite and within [tolerance::kMinCoverageGamma,
// tolerance::kMaxCoverageGamma].
void check_coverage_gamma(double gamma);

}  // namespace curvetext
