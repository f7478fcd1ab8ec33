// Shaping one line of text with HarfBuzz, with OpenType features and the
// font's current variations.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/font.hpp"

namespace curvetext {

// Throws Error(InvalidText) naming the byte offset of the first bad sequence.
void validate_utf8(std::string_view text);

struct Feature {
  std::string tag;          // "kern", "liga", ...
  std::uint32_t value = 1;  // 0 disables
};

// Parses "kern,-liga,+smcp,aalt=2" (HarfBuzz feature syntax). Throws
// Error(InvalidArgument).
std::vector<Feature> parse_features(std::string_view text);

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
  std::vector<ShapedGlyph> glyphs;
  double advance = 0.0;  // total advance in font units
};

struct ShapeOptions {
  std::vector<Feature> features;
  std::string language;   // BCP 47, empty: guessed by HarfBuzz
  std::string direction;  // "ltr", "rtl", "ttb", "btt"; empty: guessed
  std::string script;     // ISO 15924; empty: guessed
};

// Shapes valid UTF-8 (validated; throws Error(InvalidText)).
ShapedLine shape_line(const Font& font, std::string_view utf8, const ShapeOptions& options = {});

}  // namespace curvetext
