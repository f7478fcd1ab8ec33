#include "common/hud.hpp"

#include <algorithm>
#include <cstdio>

namespace example {

using curvetext::Color;
using curvetext::Rect;

namespace {

constexpr double kMargin = 16.0;     // px, window edge to bar text and to the panel
constexpr double kBarHeight = 48.0;  // px
constexpr double kBarTextPx = 24.0;
constexpr double kBarBaseline = 32.0;  // px from the top: the 24 px line centred in the bar
constexpr double kPanelWidth = 420.0;
constexpr double kPanelPadding = 14.0;
constexpr double kParagraphPx = 16.0;
constexpr Color kScoreColor{1.0f, 0.84f, 0.25f, 1.0f};
constexpr Color kFpsColor{0.55f, 1.0f, 0.6f, 1.0f};
constexpr Color kParagraphColor{0.93f, 0.93f, 0.9f, 1.0f};

constexpr const char* kParagraph =
    "This panel is a curvetext::Paragraph, wrapped at the panel's width and drawn from the glyph "
    "outlines into the app's own framebuffer. The renderer is a guest in the frame: it puts back the "
    "program, buffers, blending and depth state it changes, so the app's drawing just carries on. "
    "Kerning (AVA, Wa, To), ligatures (fi, fl) and accents (café, naïve) come from the font.";

curvetext::Paragraph layout_paragraph(curvetext::FontCollection& fonts) {
  curvetext::ParagraphStyle style;
  style.default_style.fonts = {kFontPath};
  style.default_style.size_px = kParagraphPx;
  style.default_style.color = kParagraphColor;
  style.width = kPanelWidth - 2.0 * kPanelPadding;
  return curvetext::Paragraph::layout(fonts, kParagraph, {}, style);
}

}  // namespace

std::string score_text(int frame) { return "Score " + std::to_string(1000 + 25 * frame); }

std::string fps_text(double frame_ms) {
  if (!(frame_ms > 0.0)) return "FPS --";
  char text[64];
  std::snprintf(text, sizeof text, "FPS %.1f (%.2f ms)", 1000.0 / frame_ms, frame_ms);
  return text;
}

Hud::Hud(curvetext::FontCollection& fonts, int width, int height)
    : font_(fonts.resolve(kFontPath)), width_(width), paragraph_(layout_paragraph(fonts)) {
  top_bar_ = Rect{0.0, 0.0, static_cast<double>(width), kBarHeight};
  const double panel_height = paragraph_.logical_bounds().height + 2.0 * kPanelPadding;
  panel_ = Rect{kMargin, std::max(kBarHeight + kMargin, height - kMargin - panel_height), kPanelWidth, panel_height};
}

curvetext::Vec2 Hud::paragraph_origin() const { return {panel_.x + kPanelPadding, panel_.y + kPanelPadding}; }

std::vector<TextItem> Hud::paragraph_items() const {
  const curvetext::Vec2 origin = paragraph_origin();
  return example::paragraph_items(paragraph_, origin.x, origin.y);
}

TextItem Hud::score_item(const std::string& score) const {
  return line_item(font_, score, kBarTextPx, kMargin, kBarBaseline, kScoreColor);
}

TextItem Hud::fps_item(const std::string& fps) const {
  // Right-aligned to whole pixels, so the counter does not shimmer as its width changes.
  const double x = static_cast<double>(static_cast<int>(width_ - kMargin - line_width(*font_, fps, kBarTextPx)));
  return line_item(font_, fps, kBarTextPx, x, kBarBaseline, kFpsColor);
}

std::vector<TextItem> Hud::items(const HudText& text) const {
  std::vector<TextItem> all{score_item(text.score), fps_item(text.fps)};
  for (TextItem& item : paragraph_items()) all.push_back(std::move(item));
  return all;
}

}  // namespace example
