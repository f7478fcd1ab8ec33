// Private: a text block's COLR glyphs split into passes of one colour each
// (lib/compose/text_block.cpp draws each pass as a group).
#pragma once

#include <optional>
#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/font.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext::detail {

// Glyphs of one layer index in one colour, drawn as one batch; or one glyph's
// gradient layer (its gradient placed at the glyph's pen position).
struct LayerPass {
  Color color;
  std::vector<PlacedGlyph> glyphs;
  std::optional<Gradient> gradient;  // instead of `color`
};

// Replaces each glyph of `glyphs` that has COLR layers by its layers: layer k
// of every glyph goes into a pass of layer k's colour, the passes ordered by
// layer index, so each glyph's layers are drawn in order. Glyphs without
// layers stay in `glyphs` (drawn first, in the text's colour). Foreground
// layers and gradient stops take `text`'s colour, alpha multiplied. A
// gradient layer is a pass of its own per glyph. Throws Font::color_layers'
// errors.
std::vector<LayerPass> split_color_layers(const Font& font, const Color& text, std::vector<PlacedGlyph>& glyphs);

// Draws a shaped line of a colour font (Font::color_format() not None) as
// DrawBatch::from_text places it: bitmaps as textured quads, COLR glyphs
// layer by layer, other glyphs in `options.color`. Throws as the builders
// and Renderer::draw.
void draw_color_line(Renderer& renderer, GlyphCache& cache, const Font& font, const ShapedLine& line,
                     double pixels_per_em, const Placement& placement, const DrawOptions& options);

}  // namespace curvetext::detail
