#include "compose/color_layers.hpp"

#include <unordered_map>

namespace curvetext::detail {

namespace {

bool same(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

Color with_text(const Color& text, float alpha) { return Color{text.r, text.g, text.b, text.a * alpha}; }

// A gradient layer of the glyph at `at` (font units): its gradient moved
// there, foreground stops in the text's colour.
LayerPass gradient_pass(const ColorLayer& layer, const PlacedGlyph& at, const Color& text) {
  LayerPass pass{text, {PlacedGlyph{layer.glyph_id, at.x, at.y}}, layer.gradient};
  pass.gradient->from_outline = layer.gradient->from_outline * Transform::translation(-at.x, -at.y);
  for (std::size_t k = 0; k < pass.gradient->stops.size(); ++k)
    if (layer.foreground_stops >> k & 1u) {
      Color& c = pass.gradient->stops[k].color;
      c = with_text(text, c.a);
    }
  return pass;
}

}  // namespace

std::vector<LayerPass> split_color_layers(const Font& font, const Color& text, std::vector<PlacedGlyph>& glyphs) {
  // Per layer index, its passes in the order their colours first appear.
  std::vector<std::vector<LayerPass>> by_index;
  std::vector<PlacedGlyph> plain;
  std::unordered_map<std::uint32_t, std::vector<ColorLayer>> layers_of;  // a glyph's layers, read once
  for (const PlacedGlyph& g : glyphs) {
    auto it = layers_of.find(g.glyph_id);
    if (it == layers_of.end()) it = layers_of.emplace(g.glyph_id, font.color_layers(g.glyph_id)).first;
    if (it->second.empty()) {
      plain.push_back(g);
      continue;
    }
    if (by_index.size() < it->second.size()) by_index.resize(it->second.size());
    for (std::size_t k = 0; k < it->second.size(); ++k) {
      const ColorLayer& layer = it->second[k];
      std::vector<LayerPass>& passes = by_index[k];
      if (layer.gradient) {
        passes.push_back(gradient_pass(layer, g, text));
        continue;
      }
      Color c = layer.foreground ? with_text(text, layer.color.a) : layer.color;
      LayerPass* pass = nullptr;
      for (LayerPass& p : passes)
        if (!p.gradient && same(p.color, c)) pass = &p;
      if (pass == nullptr) pass = &passes.emplace_back(LayerPass{c, {}, std::nullopt});
      pass->glyphs.push_back(PlacedGlyph{layer.glyph_id, g.x, g.y});
    }
  }
  glyphs = std::move(plain);
  std::vector<LayerPass> out;
  for (auto& passes : by_index)
    for (LayerPass& p : passes) out.push_back(std::move(p));
  return out;
}

void draw_color_line(Renderer& renderer, GlyphCache& cache, const Font& font, const ShapedLine& line,
                     double pixels_per_em, const Placement& placement, const DrawOptions& options) {
  std::vector<PlacedGlyph> glyphs;
  double pen_x = 0.0, pen_y = 0.0;
  for (const ShapedGlyph& g : line.glyphs) {
    glyphs.push_back(PlacedGlyph{g.glyph_id, pen_x + g.x_offset, pen_y + g.y_offset});
    pen_x += g.x_advance;
    pen_y += g.y_advance;
  }
  if (font.color_format() == ColorFormat::Bitmap) {
    renderer.draw(DrawBatch::from_color_bitmaps(cache, font, glyphs, pixels_per_em), placement, options);
    return;
  }
  const std::vector<LayerPass> passes = split_color_layers(font, options.color, glyphs);
  if (!glyphs.empty()) renderer.draw(DrawBatch::from_glyphs(cache, font, glyphs, pixels_per_em), placement, options);
  for (const LayerPass& pass : passes) {
    DrawOptions layer = options;
    layer.color = pass.color;
    layer.gradient = pass.gradient ? &*pass.gradient : nullptr;
    renderer.draw(DrawBatch::from_glyphs(cache, font, pass.glyphs, pixels_per_em), placement, layer);
  }
}

}  // namespace curvetext::detail
