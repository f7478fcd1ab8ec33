// EffectBatch: a line's glyphs with their outline, stroke and shadow
// (text_effects.hpp).
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/text_effects.hpp"
#include "curvetext/tolerances.hpp"
#include "core/format.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/effects.hpp"

namespace curvetext {

namespace {

void check_value(const char* what, double v, double limit) {
  if (!std::isfinite(v) || v < 0.0 || v > limit)
    throw Error(ErrorCode::InvalidArgument, std::string(what) + " must be a number from 0 to " +
                                                detail::format_number(limit) + " px, got " + detail::format_number(v));
}

void check_color(const char* what, const Color& c) {
  for (float v : {c.r, c.g, c.b, c.a})
    if (!(v >= 0.0f && v <= 1.0f))
      throw Error(ErrorCode::InvalidArgument, std::string(what) + " needs components in [0, 1]");
}

}  // namespace

void validate_text_effects(const TextEffects& e, double size_px) {
  const double widest = tolerance::kMaxTextEffectWidthEm * (std::isfinite(size_px) ? size_px : 0.0);
  check_value("an outline width", e.outline_width, widest);
  check_value("a stroke width", e.stroke_width, widest);
  check_value("a shadow's blur radius", e.shadow.blur, tolerance::kMaxShadowBlurPx);
  check_value("a shadow's x offset", std::abs(e.shadow.dx), tolerance::kMaxShadowOffsetPx);
  check_value("a shadow's y offset", std::abs(e.shadow.dy), tolerance::kMaxShadowOffsetPx);
  check_color("an outline colour", e.outline_color);
  check_color("a stroke colour", e.stroke_color);
  check_color("a shadow colour", e.shadow.color);
}

EffectBatch::EffectBatch(DrawBatch fill, std::optional<DrawBatch> outline, std::optional<DrawBatch> stroke,
                         const TextEffects& effects)
    : fill_(std::move(fill)), outline_(std::move(outline)), stroke_(std::move(stroke)), effects_(effects) {}
EffectBatch::EffectBatch(EffectBatch&&) noexcept = default;
EffectBatch& EffectBatch::operator=(EffectBatch&&) noexcept = default;
EffectBatch::~EffectBatch() = default;

EffectBatch EffectBatch::from_glyphs(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                     double pixels_per_em, const TextEffects& effects) {
  validate_text_effects(effects, pixels_per_em);
  DrawBatch fill = DrawBatch::from_glyphs(cache, font, glyphs, pixels_per_em);
  auto& impl = GlyphCacheAccess::impl(cache);
  auto effect_batch = [&](gpu::EffectKind kind, double width) -> std::optional<DrawBatch> {
    const std::uint32_t code = gpu::effect_code(kind, width, pixels_per_em);
    if (code == 0) return std::nullopt;
    return DrawBatchAccess::make(gpu::text_block(impl, font, glyphs, pixels_per_em, gpu::BlockPath::Auto, code));
  };
  std::optional<DrawBatch> outline, stroke;
  if (effects.has_outline()) outline = effect_batch(gpu::EffectKind::Outline, effects.outline_width);
  if (effects.has_stroke()) stroke = effect_batch(gpu::EffectKind::Stroke, effects.stroke_width);
  return EffectBatch(std::move(fill), std::move(outline), std::move(stroke), effects);
}

EffectBatch EffectBatch::from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em,
                                   const TextEffects& effects) {
  return from_glyphs(cache, font, gpu::placed_glyphs(line), pixels_per_em, effects);
}

void EffectBatch::draw_layer(Renderer& renderer, const Placement& at, const DrawOptions& options,
                             EffectLayer layer) const {
  DrawOptions o = options;
  switch (layer) {
    case EffectLayer::Shadow: {
      if (!effects_.has_shadow()) return;
      const DrawBatch* ink[3] = {&fill_, nullptr, nullptr};
      std::size_t n = 1;
      if (outline_) ink[n++] = &*outline_;
      if (stroke_) ink[n++] = &*stroke_;
      gpu::draw_shadow(renderer, std::span<const DrawBatch* const>(ink, n), at, options, effects_.shadow);
      return;
    }
    case EffectLayer::Outline:
      if (!outline_) return;
      o.color = effects_.outline_color;
      o.gradient = nullptr;
      renderer.draw(*outline_, at, o);
      return;
    case EffectLayer::Fill:
      renderer.draw(fill_, at, o);
      return;
    case EffectLayer::Stroke:
      if (!stroke_) return;
      o.color = effects_.stroke_color;
      o.gradient = nullptr;
      renderer.draw(*stroke_, at, o);
      return;
  }
}

void EffectBatch::draw(Renderer& renderer, const Placement& at, const DrawOptions& options) const {
  for (EffectLayer layer : {EffectLayer::Shadow, EffectLayer::Outline, EffectLayer::Fill, EffectLayer::Stroke})
    draw_layer(renderer, at, options, layer);
}

}  // namespace curvetext
