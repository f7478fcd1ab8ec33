// Test support: coverage images, exact references and their comparison
// (docs/design.md section 6), with images written when a comparison fails.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/image.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext::test {

// Coverage in [0,1] per pixel, row 0 at the top.
struct Coverage {
  int width = 0;
  int height = 0;
  std::vector<float> value;
  Coverage() = default;
  Coverage(int w, int h) : width(w), height(h), value(static_cast<std::size_t>(w) * h, 0.0f) {}
  float& at(int x, int y) { return value[static_cast<std::size_t>(y) * width + x]; }
  float at(int x, int y) const { return value[static_cast<std::size_t>(y) * width + x]; }
};

// Coverage of black drawn on white: 1 - red/255.
Coverage coverage_from_black_on_white(const Image& image);

// Exact area coverage from FreeType's AA rasterizer (FT_Outline_Render, nonzero
// fill) of `outline` placed by `placement`, rendered `supersample` times larger
// and box-filtered down, so its per-pixel error (chords, 1/64 px rounding) is
// divided by `supersample`. Conics must have weight 1 (FreeType has no
// rational curves). Cubics are passed to FreeType as cubics.
Coverage freetype_reference(const Outline& outline, const Placement& placement, int width, int height, int supersample);

// Coverage by point sampling an inside test on an n x n grid per pixel (for
// analytic shapes such as circles and rational conics).
Coverage sampled_reference(const std::function<bool(double x, double y)>& inside, int width, int height, int n);

struct CoverageStats {
  double mean_abs = 0.0;       // over the whole image
  double edge_mean_abs = 0.0;  // over the edge band
  double max_abs = 0.0;
  double ink_ratio = 1.0;  // sum(result) / sum(reference)
  std::size_t edge_pixels = 0;
};

// Edge band: pixels where either image has 0.02 < c < 0.98, dilated by one pixel.
CoverageStats compare(const Coverage& result, const Coverage& reference);

// Writes <dir>/<name>-result.png, -reference.png and -diff.png (red: result
// too dark, blue: too light) and returns the directory.
std::string write_comparison(const std::string& name, const Coverage& result, const Coverage& reference);

// The render tests' verdict on one image: prints a line for `name`, writes
// the comparison images (write_comparison) when a limit is missed, and
// expects something drawn (over 100 edge pixels), an edge-band mean error of
// at most `edge_limit` and an ink ratio within `ink_limit` of 1.
void expect_coverage(const std::string& name, const Coverage& result, const Coverage& reference,
                     const CoverageStats& stats, double edge_limit, double ink_limit);

// A shaped line as one outline in font units, each glyph at its pen position
// exactly as DrawBatch::from_text places it (pen from (0,0), y up).
Outline line_outline(const Font& font, const ShapedLine& line);

// Outline in pixel space -> the same with every point mapped by placement.
Outline place_outline(const Outline& outline, const Placement& placement);

// Pixel-space outline (y down) mapped by a projective transform (a conic
// stays a conic: control points mapped, weight times w1 / sqrt(w0 w2)).
// Lines and conics stay exact; cubics only under affine maps (throws
// otherwise).
Outline transform_outline(const Outline& outline, const Transform& transform);

}  // namespace curvetext::test
