// Text as the example apps draw it: a block of placed glyphs of one font,
// size and colour, with the Placement that puts it in the window. The
// screenshot checker (tests/examples) builds the same blocks to compute the
// exact coverage the window should show.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/font.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/renderer.hpp"

namespace example {

inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct TextItem {
  std::shared_ptr<const curvetext::Font> font;
  double pixels_per_em = 16.0;                 // on screen: picks the glyph meshes' level of detail
  std::vector<curvetext::PlacedGlyph> glyphs;  // font units, y up, from the placement's origin
  curvetext::Placement placement;
  curvetext::Color color;
};

// One line of text with its pen starting at (x, baseline), window pixels.
TextItem line_item(std::shared_ptr<const curvetext::Font> font, std::string_view utf8, double size_px, double x,
                   double baseline, curvetext::Color color);

// The width of a line of text in pixels (its advance), for right alignment.
double line_width(const curvetext::Font& font, std::string_view utf8, double size_px);

// A laid-out paragraph with its layout box's top-left at (x, y), window
// pixels: one item per run of glyphs of the same font, size and colour
// (consecutive runs merged, so a paragraph of one style is one draw).
std::vector<TextItem> paragraph_items(const curvetext::Paragraph& paragraph, double x, double y);

// A TextItem uploaded for drawing; keep it while the text stays the same
// (moving it only needs another Placement).
class ItemBatch {
 public:
  ItemBatch(curvetext::GlyphCache& cache, TextItem item);
  void draw(curvetext::Renderer& renderer) const { draw(renderer, item_.placement); }
  void draw(curvetext::Renderer& renderer, const curvetext::Placement& placement) const;
  const TextItem& item() const { return item_; }

 private:
  TextItem item_;
  curvetext::DrawBatch batch_;
};

}  // namespace example
