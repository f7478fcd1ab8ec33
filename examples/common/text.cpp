#include "common/text.hpp"

#include "curvetext/shaping.hpp"

namespace example {

using curvetext::Color;
using curvetext::Font;
using curvetext::PlacedGlyph;
using curvetext::Placement;

TextItem line_item(std::shared_ptr<const Font> font, std::string_view utf8, double size_px, double x, double baseline,
                   Color color) {
  const curvetext::ShapedLine line = curvetext::shape_line(*font, utf8);
  TextItem item;
  double pen_x = 0.0, pen_y = 0.0;
  for (const curvetext::ShapedGlyph& g : line.glyphs) {
    item.glyphs.push_back({g.glyph_id, pen_x + g.x_offset, pen_y + g.y_offset});
    pen_x += g.x_advance;
    pen_y += g.y_advance;
  }
  item.placement = Placement(size_px / font->metrics().units_per_em, x, baseline);
  item.pixels_per_em = size_px;
  item.color = color;
  item.font = std::move(font);
  return item;
}

double line_width(const Font& font, std::string_view utf8, double size_px) {
  return curvetext::shape_line(font, utf8).advance * size_px / font.metrics().units_per_em;
}

namespace {

bool same_style(const TextItem& item, const curvetext::GlyphRun& run, const Color& c) {
  return item.font == run.font && item.pixels_per_em == run.size_px && item.color.r == c.r && item.color.g == c.g &&
         item.color.b == c.b && item.color.a == c.a;
}

}  // namespace

std::vector<TextItem> paragraph_items(const curvetext::Paragraph& paragraph, double x, double y) {
  std::vector<TextItem> items;
  for (const curvetext::LayoutLine& line : paragraph.lines()) {
    for (const curvetext::GlyphRun& run : line.runs) {
      if (run.glyphs.empty()) continue;
      const Color color = paragraph.styles()[run.style].color;
      if (items.empty() || !same_style(items.back(), run, color)) {
        TextItem item;
        item.font = run.font;
        item.pixels_per_em = run.size_px;
        item.color = color;
        item.placement = Placement(run.size_px / run.font->metrics().units_per_em, x, y);
        items.push_back(std::move(item));
      }
      // Layout positions are pixels from the box's top-left, y down, with
      // the baseline in them; placed glyphs are font units from the origin, y up.
      TextItem& item = items.back();
      for (const curvetext::PositionedGlyph& g : run.glyphs)
        item.glyphs.push_back({g.id, g.x / item.placement.scale, -g.y / item.placement.scale});
    }
  }
  return items;
}

ItemBatch::ItemBatch(curvetext::GlyphCache& cache, TextItem item)
    : item_(std::move(item)),
      batch_(curvetext::DrawBatch::from_glyphs(cache, *item_.font, item_.glyphs, item_.pixels_per_em)) {}

void ItemBatch::draw(curvetext::Renderer& renderer, const Placement& placement) const {
  renderer.draw(batch_, placement, curvetext::DrawOptions(item_.color, curvetext::AntiAliasing::Full));
}

}  // namespace example
