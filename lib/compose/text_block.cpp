// A paragraph's glyph runs and decorations as draw batches (text_block.hpp).

#include "curvetext/text_block.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "curvetext/error.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/mesh.hpp"
#include "compose/color_layers.hpp"
#include "compose/effect_groups.hpp"

namespace curvetext {

struct TextBlock::Group {
  Color color;
  double size_px = 0.0;
  double scale = 1.0;  // pixels per font unit
  std::optional<DrawBatch> glyphs;
  std::optional<EffectBatch> effects;  // instead of `glyphs` when the style has effects
  std::optional<DrawBatch> bars;       // pixels, y up (placement scale 1)
  std::optional<Gradient> gradient;    // a COLR layer's, instead of the colour
};

namespace {

// Consecutive runs with the same face, size and colour become one group: one
// draw, and under full, vbaa or msaa one offscreen pass over the group's box.
struct GroupInProgress {
  const Font* font = nullptr;
  double size_px = 0.0;
  Color color;
  TextEffects effects;
  std::vector<PlacedGlyph> glyphs;  // font units, y up, from the layout box's origin
  Outline bars;

  bool takes(const GlyphRun& run, const TextStyle& style) const {
    const Color& c = style.color;
    return font == run.font.get() && size_px == run.size_px && color.r == c.r && color.g == c.g && color.b == c.b &&
           color.a == c.a && effects == style.effects;
  }
};

// A bar at `position` (font units, y up from the baseline), as thick as
// `thickness` (font units) but at least a pixel: FontMetrics' underline or
// strikeout, in layout pixels with y up.
void add_bar(Outline& bars, const LayoutLine& line, const GlyphRun& run, double position, double thickness) {
  const double scale = run.size_px / run.font->metrics().units_per_em;
  const double off = position * scale;
  const double t = std::max(thickness * scale, 1.0);
  const double top = line.baseline - off - t / 2.0;
  // Within the line's content: spaces at a line's end are not decorated.
  const double x0 = std::max(run.x, line.x), x1 = std::min(run.x + run.width, line.x + line.width);
  if (!(x1 > x0)) return;
  bars.move_to({x0, -top});
  bars.line_to({x1, -top});
  bars.line_to({x1, -(top + t)});
  bars.line_to({x0, -(top + t)});
  bars.close();
}

// Backgrounds, one outline per colour: a style's runs side by side become one
// region (the mesh is the union of its rectangles), so no seam shows between them.
struct Backgrounds {
  std::vector<std::pair<Color, Outline>> by_color;
  double size_px = 0.0;  // the largest run's, for `auto` antialiasing

  void add(const LayoutLine& line, const GlyphRun& run, const Color& c) {
    auto it = std::find_if(by_color.begin(), by_color.end(), [&](const auto& entry) {
      const Color& e = entry.first;
      return e.r == c.r && e.g == c.g && e.b == c.b && e.a == c.a;
    });
    if (it == by_color.end()) it = by_color.insert(by_color.end(), {c, Outline{}});
    const double x0 = run.x, x1 = run.x + run.width, top = line.top, bottom = line.top + line.height;
    if (!(x1 > x0)) return;
    it->second.move_to({x0, -top});
    it->second.line_to({x0, -bottom});
    it->second.line_to({x1, -bottom});
    it->second.line_to({x1, -top});
    it->second.close();
    size_px = std::max(size_px, run.size_px);
  }
};

}  // namespace

TextBlock::TextBlock() = default;
TextBlock::TextBlock(TextBlock&&) noexcept = default;
TextBlock& TextBlock::operator=(TextBlock&&) noexcept = default;
TextBlock::~TextBlock() = default;

TextBlock TextBlock::from_paragraph(GlyphCache& cache, const Paragraph& paragraph, double on_screen_scale) {
  if (!(on_screen_scale > 0.0) || !std::isfinite(on_screen_scale))
    throw Error(ErrorCode::InvalidArgument, "a text block's on-screen scale must be positive and finite");
  TextBlock block;
  block.on_screen_scale_ = on_screen_scale;
  GroupInProgress group;
  Backgrounds backgrounds;
  auto finish = [&] {
    if (group.font == nullptr) return;
    const double ppem = group.size_px * on_screen_scale;
    const ColorFormat format = group.font->color_format();
    // COLR glyphs: their layers as groups of their own, after this one.
    std::vector<detail::LayerPass> layers;
    if (format == ColorFormat::Layers) layers = detail::split_color_layers(*group.font, group.color, group.glyphs);
    Group g;
    g.color = group.color;
    g.size_px = group.size_px;
    g.scale = group.size_px / group.font->metrics().units_per_em;
    if (!group.glyphs.empty() && format != ColorFormat::Bitmap && group.effects.any())
      g.effects.emplace(
          detail::effect_batch(cache, *group.font, group.glyphs, group.size_px, on_screen_scale, group.effects));
    else if (!group.glyphs.empty())
      g.glyphs.emplace(format == ColorFormat::Bitmap
                           ? DrawBatch::from_color_bitmaps(cache, *group.font, group.glyphs, ppem)
                           : DrawBatch::from_glyphs(cache, *group.font, group.glyphs, ppem));
    if (!group.bars.empty()) g.bars.emplace(DrawBatch::from_mesh(build_mesh(group.bars)));
    block.groups_.push_back(std::move(g));
    for (const detail::LayerPass& pass : layers) {
      Group& layer = block.groups_.emplace_back();
      layer.color = pass.color;
      layer.gradient = pass.gradient;
      layer.size_px = group.size_px;
      layer.scale = group.size_px / group.font->metrics().units_per_em;
      layer.glyphs.emplace(DrawBatch::from_glyphs(cache, *group.font, pass.glyphs, ppem));
    }
  };
  for (const LayoutLine& line : paragraph.lines()) {
    for (const GlyphRun& run : line.runs) {
      const TextStyle& style = paragraph.styles()[run.style];
      if (style.background.a > 0.0f) backgrounds.add(line, run, style.background);
      if (run.glyphs.empty()) continue;
      if (!group.takes(run, style)) {
        finish();
        group = GroupInProgress{run.font.get(), run.size_px, style.color, style.effects, {}, {}};
      }
      const double scale = run.size_px / run.font->metrics().units_per_em;
      for (const PositionedGlyph& g : run.glyphs) group.glyphs.push_back(PlacedGlyph{g.id, g.x / scale, -g.y / scale});
      if (style.underline || style.strikethrough) {
        const FontMetrics m = run.font->metrics();
        if (style.underline) add_bar(group.bars, line, run, m.underline_position, m.underline_thickness);
        if (style.strikethrough) add_bar(group.bars, line, run, m.strikeout_position, m.strikeout_thickness);
      }
    }
  }
  finish();
  for (auto& [color, outline] : backgrounds.by_color) {
    if (outline.empty()) continue;
    Group g;
    g.color = color;
    g.size_px = backgrounds.size_px;
    g.bars.emplace(DrawBatch::from_mesh(build_mesh(outline)));
    block.backgrounds_.push_back(std::move(g));
  }
  return block;
}

void TextBlock::draw(Renderer& renderer, const Placement& at, const DrawOptions& options, BlockColors colors) const {
  if (colors == BlockColors::Styles)
    for (const Group& g : backgrounds_) draw_group(renderer, g, at, options, g.color, options.gradient);
  // Every group's shadow, then every outline, under every fill; strokes over them.
  const bool effects = colors == BlockColors::Styles;
  if (effects) draw_effects(renderer, at, options, EffectLayer::Shadow);
  if (effects) draw_effects(renderer, at, options, EffectLayer::Outline);
  for (const Group& g : groups_) {
    // A COLR gradient layer's own paint, unless the options' colour is asked for.
    const Gradient* gradient = colors == BlockColors::Styles && g.gradient ? &*g.gradient : options.gradient;
    draw_group(renderer, g, at, options, colors == BlockColors::Styles ? g.color : options.color, gradient);
  }
  if (effects) draw_effects(renderer, at, options, EffectLayer::Stroke);
}

void TextBlock::draw_effects(Renderer& renderer, const Placement& at, const DrawOptions& options,
                             EffectLayer layer) const {
  for (const Group& g : groups_) {
    if (!g.effects) continue;
    DrawOptions draw = options;
    draw.antialiasing = resolve_antialiasing(options.antialiasing, g.size_px * on_screen_scale_);
    Placement p = at;
    p.scale = at.scale * g.scale;
    g.effects->draw_layer(renderer, p, draw, layer);
  }
}

void TextBlock::draw(Renderer& renderer, double x, double y, const DrawOptions& options,
                     const Transform& transform) const {
  draw(renderer, Placement(1.0, x, y, transform), options);
}

void TextBlock::draw_group(Renderer& renderer, const Group& g, const Placement& at, const DrawOptions& options,
                           const Color& color, const Gradient* gradient) const {
  // The glyphs are in font units (y up), the bars and backgrounds in layout
  // pixels with y up, both from the layout box's top-left.
  Placement p = at;
  p.scale = at.scale * g.scale;
  DrawOptions draw = options;
  draw.color = color;
  draw.gradient = gradient;
  const double on_screen_px = g.size_px * on_screen_scale_;
  draw.antialiasing = g.glyphs ? resolve_antialiasing(options.antialiasing, on_screen_px, renderer, *g.glyphs, p)
                               : resolve_antialiasing(options.antialiasing, on_screen_px);
  // A colour glyph's own gradient is painted per pixel in the coverage
  // passes: modes without one draw its layers with full (the options' own
  // gradient is refused in them by the renderer, as for any batch).
  if (gradient && gradient != options.gradient &&
      (draw.antialiasing == AntiAliasing::None || draw.antialiasing == AntiAliasing::Curves ||
       (draw.antialiasing == AntiAliasing::Vbaa && draw.vbaa_ring > 0.0f)))
    draw.antialiasing = AntiAliasing::Full;
  if (g.glyphs) renderer.draw(*g.glyphs, p, draw);
  if (g.effects) g.effects->draw_layer(renderer, p, draw, EffectLayer::Fill);
  p.scale = at.scale;
  if (g.bars) renderer.draw(*g.bars, p, draw);
}

std::size_t TextBlock::group_count() const { return groups_.size(); }

}  // namespace curvetext
