// What text effects a run of text has: an outline outside the glyphs, a
// stroke centred on their outlines, and a shadow (a glow is a shadow without
// offset). A plain value type; TextStyle (layout.hpp) carries one, and
// text_effects.hpp draws them. docs/strokes.md ("Text effects").
#pragma once

#include <string_view>

#include "curvetext/color.hpp"
#include "curvetext/export.hpp"

namespace curvetext {

// A shadow of the glyphs (with their outline and stroke), drawn under them:
// offset by (dx, dy) pixels (x right, y down) of the placement drawn with,
// before its transform (Placement::origin moved; not scaled by
// Placement::scale), and blurred by a Gaussian of sigma = blur / 2
// framebuffer pixels (CSS text-shadow's blur radius). A colour with alpha 0:
// no shadow.
struct TextShadow {
  double dx = 0.0;
  double dy = 0.0;
  double blur = 0.0;  // px; 0: a sharp copy
  Color color{0, 0, 0, 0};
};

struct TextEffects {
  // Widths are in pixels at the text's size (scaled with it by the
  // placement and transform, like the glyphs).
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
  bool operator==(const TextEffects& o) const {
    auto same = [](const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; };
    return outline_width == o.outline_width && same(outline_color, o.outline_color) && stroke_width == o.stroke_width &&
           same(stroke_color, o.stroke_color) && shadow.dx == o.shadow.dx && shadow.dy == o.shadow.dy &&
           shadow.blur == o.shadow.blur && same(shadow.color, o.shadow.color);
  }
};

// Throws Error(InvalidArgument), naming the value, for a width, blur or
// offset that is NaN or infinite, a negative width or blur, a width above
// tolerance::kMaxTextEffectWidthEm of `size_px`, a blur above
// tolerance::kMaxShadowBlurPx, an offset beyond tolerance::kMaxShadowOffsetPx,
// or a colour component outside [0, 1]. Thread-safe.
CURVETEXT_API void validate_text_effects(const TextEffects& effects, double size_px);

// The outline and shadow values of the command line (`--outline 3,#000`,
// `--shadow 2,2,4,#0008`, fields separated by commas) and of markup
// (`<span outline="3 #000" shadow="2 2 4 #0008">`, by spaces): "W COLOR"
// sets the outline's width (px) and colour; "DX DY BLUR COLOR" returns a
// shadow (px). Colours as parse_color. Throws Error(InvalidArgument) naming
// the field for a missing or extra field, a number that is not finite, a
// negative width or blur, or a bad colour (the limits relative to the text
// size are validate_text_effects', checked when the text is drawn).
CURVETEXT_API void parse_outline(std::string_view text, char separator, TextEffects& effects);
CURVETEXT_API TextShadow parse_shadow(std::string_view text, char separator);

}  // namespace curvetext
