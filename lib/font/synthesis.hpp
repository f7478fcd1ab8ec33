// Private: synthetic bold and slant (FontSynthesis) on outlines and on the
// HarfBuzz font that shapes and measures a synthesised face.
#pragma once

#include <hb.h>

#include "curvetext/outline.hpp"
#include "font/harfbuzz_font.hpp"

namespace curvetext::detail {

// FreeType's FT_Outline_EmboldenXY(outline, strength, strength) on our
// outline, in its units and in double precision: every point (control points
// too) moves along the bisector of its neighbouring edges' normals, so the
// left side and the bottom stay and the right side and the top move out by
// `strength`. An outline whose control polygons have no orientation (zero
// area) is left as it is, as FreeType does.
void embolden_outline(Outline& outline, double strength);

// x += slant * y for every point (an affine map: curves stay exact).
void slant_outline(Outline& outline, double slant);

// A sub-font of `parent` whose non-zero horizontal advances are `strength`
// larger and whose glyph extents include the emboldening and the slant;
// everything else comes from `parent`. Follows the parent's variations as
// they are now: make it again after changing them.
HbFontPtr make_synthetic_font(hb_font_t* parent, hb_position_t strength, double slant);

}  // namespace curvetext::detail
