// A laid-out paragraph (layout.hpp) ready to draw into the application's own
// framebuffer, frame after frame: its glyph runs grouped by face, size and
// colour (consecutive runs), each group one DrawBatch over the glyph meshes of
// a GlyphCache, with the group's underlines and strikethroughs as one mesh;
// run backgrounds (TextStyle::background) one mesh per colour, drawn first.
// Text effects (TextStyle::effects, text_effect_style.hpp): every group's
// shadow is drawn first, then every outline, the fills, and every centred
// stroke (a bitmap colour font's glyphs have none).
// Colour glyphs (color_glyph.hpp): a COLR glyph's layers are drawn as groups
// of their own, one per layer index and colour, in the layers' order; a
// bitmap colour font's glyphs (CBDT/sbix emoji) as textured quads from the
// cache's atlas, in their own colours times the style colour's alpha.
// Built once; drawn again, moved or transformed, it changes only uniforms.
#pragma once

#include <cstddef>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/text_effects.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

// Where a text block's colours come from when it is drawn.
enum class BlockColors {
  Styles,       // each run in its style's colour, backgrounds and text effects drawn; DrawOptions::color
                // is not used
  FromOptions,  // glyphs (each COLR layer too) and decorations in DrawOptions::color, backgrounds
                // not drawn: a shadow, a selection's text, a disabled label
};

// Owns GL buffers as DrawBatch does: the context (or one sharing with it)
// that builds a block must be current when it is drawn or destroyed. Not
// thread-safe: one thread (and its context) at a time. Holds the paragraph's
// fonts (shared) but not the paragraph.
class CURVETEXT_API TextBlock {
 public:
  // `on_screen_scale`: how much larger than its layout the block will be
  // drawn (the largest stretch of the transform it is drawn with), which
  // picks the glyph meshes' level of detail and `auto` antialiasing per
  // group; 1 for text drawn at its layout size. Throws
  // Error(InvalidArgument) for a scale that is not positive and finite, and
  // the errors of DrawBatch's builders and of Font::color_layers (COLR v1
  // paints not supported are refused by name).
  static TextBlock from_paragraph(GlyphCache& cache, const Paragraph& paragraph, double on_screen_scale = 1.0);

  TextBlock(TextBlock&&) noexcept;
  TextBlock& operator=(TextBlock&&) noexcept;
  ~TextBlock();

  // Draws the block with `at` mapping its layout pixels (x right, y down
  // from the layout box's top-left) to the framebuffer's: x_px = at.scale x
  // + at.origin_x, y_px = at.origin_y + at.scale y, then at.transform, with
  // at's depth, depth offset and depth test (Placement::on_plane(mvp, w, h,
  // plane units per layout pixel, x, y) lays the box's top-left on the
  // plane's (x, y), its lines running down the plane's -y). Colours as
  // `colors` says; antialiasing, with `auto` resolved per group from its
  // pixels per em on screen, curve mode, vbaa filter, gamma and the debug
  // view from `options`. Draw with the on_screen_scale the block was built
  // for (at.scale times the transform's largest stretch). Renderer::draw's
  // GL state contract holds. Throws as Renderer::draw.
  void draw(Renderer& renderer, const Placement& at, const DrawOptions& options,
            BlockColors colors = BlockColors::Styles) const;
  // The same with Placement(1, x, y, transform): the layout box's top-left
  // at the viewport's pixel (x, y), each run in its style's colour.
  void draw(Renderer& renderer, double x, double y, const DrawOptions& options, const Transform& transform = {}) const;

  std::size_t group_count() const;

 private:
  struct Group;
  TextBlock();
  void draw_group(Renderer& renderer, const Group& g, const Placement& at, const DrawOptions& options,
                  const Color& color, const Gradient* gradient) const;
  void draw_effects(Renderer& renderer, const Placement& at, const DrawOptions& options, EffectLayer layer) const;
  std::vector<Group> backgrounds_;  // drawn first, under every group
  std::vector<Group> groups_;
  double on_screen_scale_ = 1.0;
};

}  // namespace curvetext
