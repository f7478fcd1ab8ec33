// Colour glyphs: what a colour font draws for a glyph in place of its
// outline. COLR fonts give layers, each a glyph outline filled with one colour
// (COLR v0, and the solid-colour part of COLR v1); bitmap colour fonts (CBDT
// like Noto Color Emoji, sbix) give an RGBA bitmap drawn for one size (a
// strike) that is scaled to the size drawn. Font (font.hpp) reads them;
// TextBlock (text_block.hpp) draws them.
#pragma once

#include <cstdint>
#include <vector>

#include "curvetext/color.hpp"

namespace curvetext {

// What kind of colour glyphs a face has. A face with COLR layers draws them
// even if it also has bitmaps: layers scale exactly.
enum class ColorFormat {
  None,    // outlines only
  Layers,  // COLR (v0, or v1 with solid fills): layers of outlines, each in a colour
  Bitmap,  // CBDT/CBLC or sbix: RGBA bitmaps at fixed strike sizes
};

// One layer of a COLR glyph, drawn in order, each over the ones before.
struct ColorLayer {
  std::uint32_t glyph_id = 0;  // the glyph whose outline is the layer's shape
  Color color;                 // straight alpha, sRGB (the palette's entry times the paint's alpha)
  // Palette entry 0xFFFF: the text's own colour, its alpha times color.a
  // (color.r/g/b are then unused).
  bool foreground = false;
};

// One glyph's bitmap from a bitmap colour font, at the strike chosen for the
// size asked for.
struct ColorBitmap {
  int width = 0, height = 0;  // pixels; 0 x 0 for a glyph without a bitmap (a space)
  double strike_ppem = 0.0;   // the pixels per em the bitmap was made for
  int strike = 0;             // index of that strike in the font
  // The bitmap's top-left corner from the glyph origin, in strike pixels,
  // x right and y up (top > 0 above the baseline).
  double left = 0.0, top = 0.0;
  // width * height * 4 bytes, rows from the top: RGBA, premultiplied alpha,
  // sRGB-encoded (as FreeType decodes CBDT's and sbix's PNGs).
  std::vector<std::uint8_t> rgba;
};

}  // namespace curvetext
