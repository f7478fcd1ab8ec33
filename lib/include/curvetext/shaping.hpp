// Shaping one line of text with HarfBuzz, with OpenType features and the
// font's current variations.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/font.hpp"

namespace curvetext {

// Strict UTF-8 (no overlong forms, surrogates or code points above
// U+10FFFF). Throws Error(InvalidText) naming the byte offset of the first
// bad sequence.
CURVETEXT_API void validate_utf8(std::string_view text);

struct Feature {
  std::string tag;          // "kern", "liga", ...
  std::uint32_t value = 1;  // 0 disables
};

// Parses "kern,-liga,+smcp,aalt=2" (HarfBuzz's feature syntax, which
// hb_feature_from_string reads; kept here because features are a shaping
// concept callers type, as in CSS font-feature-settings). A blank text gives
// none. Throws Error(InvalidArgument) naming the bad item, also for a
// character range ("kern[3:5]"), which Feature cannot carry.
CURVETEXT_API std::vector<Feature> parse_features(std::string_view text);

struct ShapedGlyph {
  std::uint32_t glyph_id = 0;
  std::uint32_t cluster = 0;  // UTF-8 byte offset of the cluster in the text
  // Pen-relative position and advance in font units (unrounded: HarfBuzz runs
  // at a scale of units_per_em so nothing is quantised).
  double x_offset = 0.0;
  double y_offset = 0.0;
  double x_advance = 0.0;
  double y_advance = 0.0;
};

struct ShapedLine {
  std::vector<ShapedGlyph> glyphs;  // in visual order (left to right for horizontal text)
  double advance = 0.0;             // total advance in font units
};

struct ShapeOptions {
  std::vector<Feature> features;
  std::string language;   // BCP 47, empty: guessed by HarfBuzz
  std::string direction;  // "ltr", "rtl", "ttb", "btt"; empty: guessed
  std::string script;     // ISO 15924; empty: guessed
};

// Shapes one line of UTF-8 with HarfBuzz at the font's current variations
// and synthesis (wider advances, slanted offsets: FontSynthesis).
// May be called from several threads at once, on the same font too. Throws
// Error(InvalidText) for invalid UTF-8 or a text over INT_MAX bytes,
// Error(InvalidArgument) for a bad direction, script or language.
CURVETEXT_API ShapedLine shape_line(const Font& font, std::string_view utf8, const ShapeOptions& options = {});

}  // namespace curvetext
