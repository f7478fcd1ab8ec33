// Text effects' GPU side (lib/gpu/effects.cpp): the cache keys and outlines
// of effect meshes (a glyph's outline ring and centred stroke), and the
// shadow pass. Private to the library.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "curvetext/draw_batch.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/stroke.hpp"
#include "curvetext/text_effects.hpp"

namespace curvetext::gpu {

// What an effect mesh holds: the ring outside the glyph (the glyph dilated
// minus the glyph) or the stroke centred on its outline.
enum class EffectKind : std::uint32_t { Outline = 1, Stroke = 2 };

// The glyph cache's key of an effect of `width_px` at `pixels_per_em`: the
// kind and the width in ems in steps of 1 / tolerance::kTextEffectWidthStepsPerEm;
// 0 (no mesh) when the width rounds to no step.
std::uint32_t effect_code(EffectKind kind, double width_px, double pixels_per_em);

// Room the effect outlines reuse from one glyph to the next.
struct EffectScratch {
  Outline boundary, dilated;
  std::vector<ShapeContour> contours;
  Stroker stroker;
};

// Replaces `glyph` (font units) by the outline of effect `code`: for
// Outline, the dilated glyph's boundary plus the glyph's boundary reversed
// (nonzero winding 1 in the ring, 0 inside the glyph); for Stroke, the
// stroke loops. `tolerance` (font units) is the cubic tolerance of the
// mesh; offsets are fitted within a quarter of it. Throws the stroker's and
// fill_boundary's errors.
void effect_outline(std::uint32_t code, double units_per_em, double tolerance, Outline& glyph, EffectScratch& scratch);

// The GL objects of the shadow passes, one per Renderer (renderer.cpp holds it).
struct EffectPasses;
std::shared_ptr<EffectPasses>& effect_passes(Renderer& renderer);

// Draws the shadow of `batches` (coverage of their union at `at` moved by
// the shadow's offset, in pixels of the placement) blurred and composited
// under what is drawn next, at the placement's depth. GL state as
// Renderer::draw.
void draw_shadow(Renderer& renderer, std::span<const DrawBatch* const> batches, const Placement& at,
                 const DrawOptions& options, const TextShadow& shadow);

}  // namespace curvetext::gpu
