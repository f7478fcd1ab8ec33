// A laid-out paragraph as SVG: each glyph run's outlines, positioned, as one
// <path> in pixel coordinates (y down) filled with the run's colour, in an
// image of the size the PNG would have (paragraph_image.hpp, no transform).
#pragma once

#include <string>

#include "curvetext/color.hpp"
#include "curvetext/layout.hpp"

namespace curvetext::cli {

// Outline segments become L (lines), Q (conics of weight 1) and C (cubics).
// Throws Error(InvalidArgument) for what SVG paths cannot say or this writer
// does not draw, by name: a conic of weight != 1 (no TrueType/CFF glyph has
// one), underline, strikethrough and span backgrounds; and the errors of
// paragraph_image_size for the image's size.
std::string paragraph_svg(const Paragraph& paragraph, double margin_px, Color background);

}  // namespace curvetext::cli
