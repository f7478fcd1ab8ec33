// Private interface of font/ for the stages after it: what layout and
// composition ask of a face beyond Font's public API, read through the
// HarfBuzz font that shapes and draws it (a synthesised face's sub-font).
// Shaping itself is in font/shaper.hpp; FreeType and the Font's state stay
// inside font/.
#pragma once

#include <hb.h>

#include <cstdint>
#include <vector>

#include "curvetext/font.hpp"

namespace curvetext::detail {

// hb_style_get_value: weight (100-900), italic (0 or 1), slant ratio, at the
// font's current variations.
float style_value(const Font& font, hb_style_tag_t tag);

// The horizontal advance of `glyph` in font units, synthesis included.
double glyph_h_advance(const Font& font, std::uint32_t glyph);

// The ink box of `glyph` in font units (y up from the baseline to its top);
// false when the font has none for it.
bool glyph_extents(const Font& font, std::uint32_t glyph, hb_glyph_extents_t& extents);

// Whether the face has a table with this tag (and it is not empty).
bool has_table(const Font& font, hb_tag_t tag);

// The axis values of named instance `instance` (1-based, as fontconfig and
// FreeType number them in the upper 16 bits of a face index) of a variable
// face. Throws Error(FontInvalid) when the face has no such instance.
std::vector<Variation> named_instance_variations(const Font& font, int instance);

}  // namespace curvetext::detail
