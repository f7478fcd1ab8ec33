// A text block group's effects (effect_groups.hpp).
#include "compose/effect_groups.hpp"

namespace curvetext::detail {

EffectBatch effect_batch(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs, double size_px,
                         double on_screen_scale, const TextEffects& effects) {
  validate_text_effects(effects, size_px);
  TextEffects built = effects;
  built.outline_width *= on_screen_scale;
  built.stroke_width *= on_screen_scale;
  return EffectBatch::from_glyphs(cache, font, glyphs, size_px * on_screen_scale, built);
}

}  // namespace curvetext::detail
