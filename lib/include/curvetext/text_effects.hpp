// Drawing text with its effects (text_effect_style.hpp): EffectBatch draws
// one line or any placed glyphs with an outline, a centred stroke and a
// shadow; TextBlock (text_block.hpp) draws a paragraph's styles' effects.
// docs/strokes.md ("Text effects") has the model, the caching and the limits.
#pragma once

#include <optional>
#include <span>

#include "curvetext/draw_batch.hpp"
#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_effect_style.hpp"

namespace curvetext {

// The layers an EffectBatch draws, bottom to top.
enum class EffectLayer { Shadow, Outline, Fill, Stroke };

// One font's glyphs with their effects, drawn in one call: shadow, outline,
// fill, stroke. Effect meshes come from the GlyphCache as fills do, per
// glyph and per width bucket (docs/strokes.md). Same ownership, context and
// thread rules as DrawBatch.
class CURVETEXT_API EffectBatch {
 public:
  // As DrawBatch::from_glyphs / from_text; `pixels_per_em` is also the size
  // the effects' pixel widths are measured at (widths scale with the
  // placement like the glyphs). Throws as those and validate_text_effects,
  // and Error(Geometry) when an effect's outline cannot be meshed.
  static EffectBatch from_glyphs(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                 double pixels_per_em, const TextEffects& effects);
  static EffectBatch from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em,
                               const TextEffects& effects);

  EffectBatch(EffectBatch&&) noexcept;
  EffectBatch& operator=(EffectBatch&&) noexcept;
  ~EffectBatch();

  // Draws shadow, outline, the glyphs in options.color, then the stroke,
  // each as Renderer::draw does (same placement, antialiasing, depth and GL
  // state contract). The shadow is offset by (dx, dy) pixels of the
  // placement (its origin moved, before its transform) and blurred in
  // framebuffer pixels. Throws as Renderer::draw.
  void draw(Renderer& renderer, const Placement& at, const DrawOptions& options) const;
  // One layer only (a text block draws every group's shadow, then every
  // outline, fill and stroke, so no group's shadow or outline covers
  // another's fill). The fill is drawn in options.color, the others in
  // their effect's colour.
  void draw_layer(Renderer& renderer, const Placement& at, const DrawOptions& options, EffectLayer layer) const;

  const DrawBatch& glyphs() const { return fill_; }
  const DrawBatch* outline() const { return outline_ ? &*outline_ : nullptr; }
  const DrawBatch* stroke() const { return stroke_ ? &*stroke_ : nullptr; }
  const TextEffects& effects() const { return effects_; }

 private:
  EffectBatch(DrawBatch fill, std::optional<DrawBatch> outline, std::optional<DrawBatch> stroke,
              const TextEffects& effects);
  DrawBatch fill_;
  std::optional<DrawBatch> outline_;
  std::optional<DrawBatch> stroke_;
  TextEffects effects_;
};

}  // namespace curvetext
