// Colour glyphs: what a colour font draws for a glyph in place of its
// outline. COLR fonts give layers, each a glyph outline filled with one colour
// or (COLR v1) a gradient; bitmap colour fonts (CBDT
// like Noto Color Emoji, sbix) give an RGBA bitmap drawn for one size (a
// strike) that is scaled to the size drawn. Font (font.hpp) reads them;
// TextBlock (text_block.hpp) draws them.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/paint.hpp"

namespace curvetext {

// What kind of colour glyphs a face has. A face with COLR layers draws them
// even if it also has bitmaps: layers scale exactly.
enum class ColorFormat {
  None,    // outlines only
  Layers,  // COLR (v0, or v1): layers of outlines, each in a colour or a gradient
  Bitmap,  // CBDT/CBLC or sbix: RGBA bitmaps at fixed strike sizes
};

// One layer of a COLR glyph, drawn in order, each over the ones before.
struct ColorLayer {
  std::uint32_t glyph_id = 0;  // the glyph whose outline is the layer's shape
  Color color;                 // straight alpha, sRGB (the palette's entry times the paint's alpha)
  // Palette entry 0xFFFF: the text's own colour, its alpha times color.a
  // (color.r/g/b are then unused).
  bool foreground = false;
  // A COLR v1 gradient that fills the layer instead of `color`. Its
  // coordinates are the glyph's font units from its origin, y up (so a
  // sweep turns counter-clockwise); from_outline carries the paint's
  // transforms. Stops come from the palette times their alpha.
  std::optional<Gradient> gradient;
  // Bit k set: the gradient's stop k is the text's colour, its alpha times
  // the stop's color.a (palette entry 0xFFFF).
  std::uint32_t foreground_stops = 0;
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
