#include "curvetext/text_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "compose/check_style.hpp"
#include "compose/color_layers.hpp"
#include "core/format.hpp"
#include "layout/cluster_limit.hpp"

namespace curvetext {

TextImageLayout layout_text_image(const Font& font, std::string_view text, const TextImageOptions& options) {
  if (!std::isfinite(options.size_px) || options.size_px <= 0.0)
    throw Error(ErrorCode::InvalidArgument,
                "size must be a positive number of pixels, got " + detail::format_number(options.size_px));
  if (options.size_px > tolerance::kMaxPixelsPerEm)
    throw Error(ErrorCode::InvalidArgument, "size " + detail::format_number(options.size_px) +
                                                " px is above the limit of " +
                                                detail::format_number(tolerance::kMaxPixelsPerEm) + " px");
  if (!std::isfinite(options.margin_px) || options.margin_px < 0.0 || options.margin_px > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "margin must be between 0 and the largest image side");
  check_coverage_gamma(options.gamma);
  if (text.empty()) throw Error(ErrorCode::InvalidText, "the text is empty");
  if (text.size() > tolerance::kMaxTextBytes)
    throw Error(ErrorCode::InvalidText, "text of " + std::to_string(text.size()) + " bytes is over the limit of " +
                                            std::to_string(tolerance::kMaxTextBytes) + " bytes");
  validate_utf8(text);
  detail::check_cluster_lengths(text);

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
  layout.placement.scale = scale;
  layout.placement.origin_x = options.margin_px;
  layout.placement.origin_y = options.margin_px + layout.ascender_px;
  const ImageFrame frame = transform_frame(w, h, options.transform);
  layout.width = frame.width;
  layout.height = frame.height;
  layout.placement.transform = frame.transform;
  layout.largest_stretch = frame.largest_stretch;
  return layout;
}

Image render_text_image(Renderer& renderer, GlyphCache& cache, const Font& font, const TextImageLayout& layout,
                        const TextImageOptions& options) {
  if (font.color_format() != ColorFormat::None) {  // COLR layers or bitmap emoji
    const double ppem = options.size_px * layout.largest_stretch;
    ImageTarget target;
    target.begin(layout.width, layout.height, options.background, options.blending);
    detail::draw_color_line(renderer, cache, font, layout.line, ppem, layout.placement,
                            draw_options(options, options.foreground, ppem));
    return target.read_pixels();
  }
  DrawBatch batch = DrawBatch::from_text(cache, font, layout.line, options.size_px * layout.largest_stretch);
  // auto: full where the block draws from its bands, else per pixels per em
  // on screen, as for paragraphs (image_style.hpp).
  const double on_screen_px = options.size_px * layout.largest_stretch;
  DrawOptions draw = draw_options(options, options.foreground, on_screen_px);
  draw.antialiasing = resolve_antialiasing(options.antialiasing, on_screen_px, renderer, batch, layout.placement);
  ImageTarget target;
  target.begin(layout.width, layout.height, options.background, options.blending);
  renderer.draw(batch, layout.placement, draw);
  return target.read_pixels();
}

}  // namespace curvetext
