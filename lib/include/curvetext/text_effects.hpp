// Text effects: an outline outside the glyphs, a stroke centred on their
// outlines, and a shadow (a glow is a shadow without offset). TextStyle
// (layout.hpp) carries them for paragraphs and text blocks; EffectBatch
// draws one line or any placed glyphs with them. docs/strokes.md ("Text
// effects") has the model, the caching and the limits.
#pragma once

#include <optional>
#include <span>

#include "curvetext/color.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext {

// A shadow of the glyphs (with their outline and stroke), drawn under them:
// offset by (dx, dy) layout pixels (x right, y down, before the placement's
// transform) and blurred by a Gaussian of sigma = blur / 2 framebuffer pixels
// (CSS text-shadow's blur radius). A colour with alpha 0: no shadow.
struct TextShadow {
  double dx = 0.0;
  double dy = 0.0;
  double blur = 0.0;  // px; 0: a sharp copy
  Color color{0, 0, 0, 0};
};

struct TextEffects {
  // The glyphs dilated by `outline_width` px with round joins (every point
  // within that distance of a glyph), drawn under the fill and only where
  // the glyph is not: a translucent fill does not show it. 0: none.
  double outline_width = 0.0;
  Color outline_color{0, 0, 0, 1};
  // A stroke `stroke_width` px wide centred on the glyph outlines (round
  // joins), drawn over the fill. 0: none.
  double stroke_width = 0.0;
  Color stroke_color{0, 0, 0, 1};
  TextShadow shadow;

  // A shadow without offset.
  static TextShadow glow(double blur, Color color) { return TextShadow{0.0, 0.0, blur, color}; }
  bool has_outline() const { return outline_width > 0.0 && outline_color.a > 0.0f; }
  bool has_stroke() const { return stroke_width > 0.0 && stroke_color.a > 0.0f; }
  bool has_shadow() const { return shadow.color.a > 0.0f; }
  bool any() const { return has_outline() || has_stroke() || has_shadow(); }
  bool operator==(const TextEffects& o) const;
};

// Throws Error(InvalidArgument), naming the value, for a width, blur or
// offset that is NaN or infinite, a negative width or blur, a width above
// tolerance::kMaxTextEffectWidthEm of `size_px`, a blur above
// tolerance::kMaxShadowBlurPx, an offset beyond tolerance::kMaxShadowOffsetPx,
// or a colour component outside [0, 1]. Thread-safe.
CURVETEXT_API void validate_text_effects(const TextEffects& effects, double size_px);

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
