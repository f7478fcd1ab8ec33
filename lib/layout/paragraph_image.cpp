// Drawing a Paragraph through DrawBatch/GlyphCache (see paragraph_image.hpp).

#include "curvetext/paragraph_image.hpp"

#include <hb-ot.h>

#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/tolerances.hpp"
#include "font/font_impl.hpp"

namespace curvetext {

ImageFrame paragraph_image_frame(const Paragraph& paragraph, const ParagraphImageOptions& options) {
  if (!std::isfinite(options.margin_px) || options.margin_px < 0.0 || options.margin_px > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "margin must be between 0 and the largest image side");
  const Rect box = paragraph.logical_bounds();
  const double w = std::ceil(2.0 * options.margin_px + std::max(0.0, box.x + box.width));
  const double h = std::ceil(2.0 * options.margin_px + std::max(0.0, box.y + box.height));
  if (!(w >= 1.0 && h >= 1.0) || w > tolerance::kMaxImageSidePx || h > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "the image would be " + std::to_string(static_cast<long long>(w)) + "x" +
                                                std::to_string(static_cast<long long>(h)) +
                                                " px; the largest side allowed is " +
                                                std::to_string(static_cast<int>(tolerance::kMaxImageSidePx)));
  return transform_frame(w, h, options.transform);
}

ImageSize paragraph_image_size(const Paragraph& paragraph, const ParagraphImageOptions& options) {
  const ImageFrame frame = paragraph_image_frame(paragraph, options);
  return {frame.width, frame.height};
}

Image render_paragraph_image(Renderer& renderer, GlyphCache& cache, const Paragraph& paragraph,
                             const ParagraphImageOptions& options) {
  const ImageFrame frame = paragraph_image_frame(paragraph, options);
  check_coverage_gamma(options.gamma);
  renderer.begin(frame.width, frame.height, options.background, options.blending);
  for (const LayoutLine& line : paragraph.lines()) {
    for (const GlyphRun& run : line.runs) {
      if (run.glyphs.empty()) continue;
      const TextStyle& style = paragraph.styles()[run.style];
      const double scale = run.size_px / run.font->metrics().units_per_em;
      // DrawBatch places glyphs from pen (0, 0) in font units: give each glyph
      // its absolute position as an offset, with no advance.
      ShapedLine shaped;
      for (const PositionedGlyph& g : run.glyphs) {
        ShapedGlyph sg;
        sg.glyph_id = g.id;
        sg.cluster = g.cluster;
        sg.x_offset = g.x / scale;
        sg.y_offset = -g.y / scale;
        shaped.glyphs.push_back(sg);
      }
      // Pixels per em on screen: the level of detail and what `auto` picks.
      const double on_screen_px = run.size_px * frame.largest_stretch;
      const DrawOptions draw = draw_options(options, style.color, on_screen_px);
      const Placement placement{scale, options.margin_px, options.margin_px, frame.transform};
      renderer.draw(DrawBatch::from_text(cache, *run.font, shaped, on_screen_px), placement, draw);

      if (!style.underline && !style.strikethrough) continue;
      // Bars from the font's post / OS/2 metrics, as thick as it says.
      Outline bars;
      auto bar = [&](hb_ot_metrics_tag_t offset_tag, hb_ot_metrics_tag_t size_tag, double fallback_offset) {
        hb_position_t offset = 0, thickness = 0;
        const double upem = run.font->metrics().units_per_em;
        const double off = hb_ot_metrics_get_position(run.font->impl().hb_font, offset_tag, &offset)
                               ? offset * scale
                               : fallback_offset * run.size_px;
        double t = hb_ot_metrics_get_position(run.font->impl().hb_font, size_tag, &thickness) ? thickness * scale
                                                                                              : upem * 0.05 * scale;
        t = std::max(t, 1.0);
        // Outline y is up: y_px = margin - y  =>  y = margin - y_px (placement scale 1).
        const double top = line.baseline - off - t / 2.0;
        const double x0 = run.x, x1 = run.x + run.width;
        bars.move_to({x0, -top});
        bars.line_to({x1, -top});
        bars.line_to({x1, -(top + t)});
        bars.line_to({x0, -(top + t)});
        bars.close();
      };
      if (style.underline) bar(HB_OT_METRICS_TAG_UNDERLINE_OFFSET, HB_OT_METRICS_TAG_UNDERLINE_SIZE, -0.1);
      if (style.strikethrough) bar(HB_OT_METRICS_TAG_STRIKEOUT_OFFSET, HB_OT_METRICS_TAG_STRIKEOUT_SIZE, 0.3);
      renderer.draw(DrawBatch::from_mesh(build_mesh(bars)),
                    Placement{1.0, options.margin_px, options.margin_px, frame.transform}, draw);
    }
  }
  return renderer.read_pixels();
}

}  // namespace curvetext
