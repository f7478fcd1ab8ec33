// Test support: exact area coverage of the nonzero-winding union of an outline
// (docs/design.md section 6), the reference that overlapping contours need.
// FreeType's AA rasterizer sums the windings of overlapping contours per cell
// and so over-covers edge pixels where contours overlap; this one does not.
//
// Method: the outline is flattened to within kUnionFlatnessPx, cut into
// y-monotone chains, and each pixel row is split into sub-slabs at every
// chain end and every crossing of two chains inside the row. Inside a
// sub-slab no two chains cross, so one left-to-right walk at its middle
// decides which chains bound the nonzero region; each of those adds the exact
// area between itself and the pixel columns (closed form for a straight piece
// against a column strip). The only approximation is the flattening.
#pragma once

#include "curvetext/outline.hpp"
#include "support/coverage.hpp"

namespace curvetext::test {

// Largest distance, in pixels, between a curve and the polyline that replaces
// it (the control points' distance to the chord, which bounds the curve's).
// A boundary displaced by e changes a pixel's coverage by at most sqrt(2)*e,
// so the reference is within 0.003 of the exact coverage of the curves, well
// below the 0.01-level errors it is used to judge.
inline constexpr double kUnionFlatnessPx = 1.0 / 512.0;

// Adds the exact nonzero-union coverage of `pixel_outline` (already in pixel
// space: y down, pixel (i,j) covers [i,i+1]x[j,j+1]) to `target`, clipped to
// the image. Callers fill disjoint regions of one image by calling it per
// shape. Lines, rational conics of any positive weight and cubics.
void add_union_coverage(const Outline& pixel_outline, Coverage& target, double flatness_px = kUnionFlatnessPx);

// A new width x height image holding the coverage of `pixel_outline`.
Coverage union_coverage(const Outline& pixel_outline, int width, int height, double flatness_px = kUnionFlatnessPx);

}  // namespace curvetext::test
