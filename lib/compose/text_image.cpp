#include "curvetext/text_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"

namespace curvetext {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

TextImageLayout layout_text_image(const Font& font, std::string_view text, const TextImageOptions& options) {
  if (!std::isfinite(options.size_px) || options.size_px <= 0.0)
    throw Error(ErrorCode::InvalidArgument, "size must be a positive number of pixels, got " + number(options.size_px));
  if (options.size_px > tolerance::kMaxPixelsPerEm)
    throw Error(ErrorCode::InvalidArgument, "size " + number(options.size_px) + " px is above the limit of " +
                                                number(tolerance::kMaxPixelsPerEm) + " px");
  if (!std::isfinite(options.margin_px) || options.margin_px < 0.0 || options.margin_px > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "margin must be between 0 and the largest image side");
  check_coverage_gamma(options.gamma);
  if (text.empty()) throw Error(ErrorCode::InvalidText, "the text is empty");
  validate_utf8(text);

  TextImageLayout layout;
  layout.line = shape_line(font, text, options.shaping);
  const FontMetrics m = font.metrics();
  const double scale = options.size_px / m.units_per_em;
  layout.ascender_px = m.ascender * scale;
  layout.descender_px = m.descender * scale;
  const double advance_px = layout.line.advance * scale;
  const double w = std::ceil(2.0 * options.margin_px + std::abs(advance_px));
  const double h = std::ceil(2.0 * options.margin_px + layout.ascender_px - layout.descender_px);
  if (!(w >= 1.0 && h >= 1.0) || w > tolerance::kMaxImageSidePx || h > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "the image would be " + std::to_string(static_cast<long long>(w)) + "x" +
                                                std::to_string(static_cast<long long>(h)) +
                                                " px; the largest side allowed is " +
                                                std::to_string(static_cast<int>(tolerance::kMaxImageSidePx)));
  layout.width = static_cast<int>(w);
  layout.height = static_cast<int>(h);
  layout.placement.scale = scale;
  layout.placement.origin_x = options.margin_px;
  layout.placement.origin_y = options.margin_px + layout.ascender_px;
  if (!options.transform.is_identity()) {
    options.transform.validate();
    const Transform t = options.transform.about({w / 2.0, h / 2.0});
    Box box;
    double stretch = 0.0;
    for (Vec2 c : {Vec2{0, 0}, Vec2{w, 0}, Vec2{0, h}, Vec2{w, h}}) {
      const double cw = t.w(c) / t.m[8];
      if (!(cw > tolerance::kMinPerspectiveW))
        throw Error(ErrorCode::InvalidArgument,
                    "the transform puts part of the text behind the viewer (use a smaller perspective angle or a larger distance)");
      box.add(t.apply(c));
      stretch = std::max(stretch, t.largest_stretch(c));
    }
    const double tw = std::ceil(box.max.x - box.min.x), th = std::ceil(box.max.y - box.min.y);
    if (!(tw >= 1.0 && th >= 1.0) || tw > tolerance::kMaxImageSidePx || th > tolerance::kMaxImageSidePx)
      throw Error(ErrorCode::InvalidArgument, "the transformed image would be " + number(tw) + "x" + number(th) +
                                                  " px; the largest side allowed is " +
                                                  std::to_string(static_cast<int>(tolerance::kMaxImageSidePx)));
    layout.width = static_cast<int>(tw);
    layout.height = static_cast<int>(th);
    layout.placement.transform = Transform::translation(-box.min.x, -box.min.y) * t;
    layout.largest_stretch = stretch;
  }
  return layout;
}

Image render_text_image(Renderer& renderer, GlyphCache& cache, const Font& font, const TextImageLayout& layout,
                        const TextImageOptions& options) {
  DrawBatch batch = DrawBatch::from_text(cache, font, layout.line, options.size_px * layout.largest_stretch);
  check_coverage_gamma(options.gamma);
  renderer.begin(layout.width, layout.height, options.background, options.blending);
  DrawOptions draw;
  draw.color = options.foreground;
  draw.antialiasing = options.antialiasing;
  // auto: vbaa up to kAutoVbaaMaxPx on screen, full above (bench/quality_bench:
  // vbaa's edge error is below full's at every size from 8 to 384 px).
  if (draw.antialiasing == AntiAliasing::Auto)
    draw.antialiasing = options.size_px * layout.largest_stretch <= tolerance::kAutoVbaaMaxPx ? AntiAliasing::Vbaa
                                                                                              : AntiAliasing::Full;
  draw.curve_mode = options.curve_mode;
  draw.vbaa_ring = options.vbaa_ring;
  draw.gamma = options.gamma;
  draw.debug = options.debug;
  renderer.draw(batch, layout.placement, draw);
  return renderer.read_pixels();
}

}  // namespace curvetext
