// The heads-up display both example apps draw over their scene: a top bar
// with the score (left) and an FPS counter (right), and a panel at the bottom
// left with a wrapped paragraph. The app draws the bar and the panel (its own
// GL); this says where they go and builds their text.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "common/text.hpp"

namespace example {

struct HudText {
  std::string score;
  std::string fps;
};

// Deterministic per frame, so screenshots are reproducible.
std::string score_text(int frame);
// From the last frame's duration; "FPS --" before there is one.
std::string fps_text(double frame_ms);

class Hud {
 public:
  // Lays out the paragraph once, for a window of width x height pixels.
  Hud(curvetext::FontCollection& fonts, int width, int height);

  // Window pixels, y down.
  const curvetext::Rect& top_bar() const { return top_bar_; }
  const curvetext::Rect& panel() const { return panel_; }
  // The background colours the apps fill them with (straight alpha).
  static constexpr curvetext::Color kBarColor{0.04f, 0.05f, 0.09f, 0.78f};
  static constexpr curvetext::Color kPanelColor{0.05f, 0.06f, 0.10f, 0.85f};

  // The paragraph, which never changes (the apps make one curvetext::TextBlock
  // of it), and where its layout box's top-left goes (window pixels).
  const curvetext::Paragraph& paragraph() const { return paragraph_; }
  curvetext::Vec2 paragraph_origin() const;
  // The same as items placed one per run: what the checker compares with.
  std::vector<TextItem> paragraph_items() const;
  // The score and the FPS counter, which change while the app runs.
  TextItem score_item(const std::string& score) const;
  TextItem fps_item(const std::string& fps) const;
  // Everything, in drawing order: score, FPS, paragraph.
  std::vector<TextItem> items(const HudText& text) const;

 private:
  std::shared_ptr<const curvetext::Font> font_;
  int width_ = 0;
  curvetext::Paragraph paragraph_;
  curvetext::Rect top_bar_, panel_;
};

}  // namespace example
