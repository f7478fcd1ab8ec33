// Private: a text block group's glyphs with their style's effects
// (lib/compose/text_block.cpp).
#pragma once

#include <span>

#include "curvetext/text_effects.hpp"

namespace curvetext::detail {

// The group's EffectBatch at size_px * on_screen_scale pixels per em, its
// widths (px at size_px) scaled as much. Throws validate_text_effects'
// errors (widths measured against size_px) and EffectBatch's.
EffectBatch effect_batch(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs, double size_px,
                         double on_screen_scale, const TextEffects& effects);

}  // namespace curvetext::detail
