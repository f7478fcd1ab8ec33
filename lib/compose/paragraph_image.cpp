// Drawing a Paragraph through DrawBatch/GlyphCache (see paragraph_image.hpp).

#include "curvetext/paragraph_image.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/text_block.hpp"
#include "curvetext/tolerances.hpp"

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
  // The style's options (gamma checked); `auto` stays for the block to
  // resolve per group of runs.
  DrawOptions draw = draw_options(options, Color{0, 0, 0, 1}, 1.0);
  draw.antialiasing = options.antialiasing;
  const TextBlock block = TextBlock::from_paragraph(cache, paragraph, frame.largest_stretch);
  ImageTarget target;
  target.begin(frame.width, frame.height, options.background, options.blending);
  block.draw(renderer, options.margin_px, options.margin_px, draw, frame.transform);
  return target.read_pixels();
}

}  // namespace curvetext
