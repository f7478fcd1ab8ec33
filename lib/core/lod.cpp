#include "curvetext/lod.hpp"

#include <algorithm>
#include <cmath>

#include "curvetext/tolerances.hpp"

namespace curvetext {

int lod_for_scale(double pixels_per_unit, double units_per_em) {
  const double ppem = pixels_per_unit * units_per_em;
  if (!(ppem > 0.0) || !std::isfinite(ppem)) return tolerance::kMinLodLog2;
  const int band = static_cast<int>(std::ceil(std::log2(ppem)));
  return std::clamp(band, tolerance::kMinLodLog2, tolerance::kMaxLodLog2);
}

double cubic_tolerance_for_lod(int lod, double units_per_em) {
  // At the band's largest scale 2^lod px/em, one pixel is units_per_em / 2^lod units.
  return tolerance::kCubicApproximationPx * units_per_em / std::ldexp(1.0, lod);
}

}  // namespace curvetext
