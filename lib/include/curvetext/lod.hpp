// Level of detail for meshes of outlines with cubics: one mesh per
// power-of-two band of drawn scale, so the cubic approximation stays within
// tolerance::kCubicApproximationPx of the true curve at the band's largest
// scale. Outlines without cubics are exact at every scale and use one mesh.
#pragma once

#include "curvetext/export.hpp"

namespace curvetext {

// Band index for a drawn scale in pixels per outline unit (ppem / upem for
// glyphs): ceil(log2(pixels per em)), clamped to the tolerance.hpp range.
CURVETEXT_API int lod_for_scale(double pixels_per_unit, double units_per_em);

// Cubic tolerance, in outline units, for meshes of band `lod`
// (tolerance::kCubicApproximationPx at the band's largest scale).
CURVETEXT_API double cubic_tolerance_for_lod(int lod, double units_per_em);

}  // namespace curvetext
