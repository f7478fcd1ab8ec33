// A laid-out paragraph (layout.hpp) to an image through the renderer: one
// DrawBatch per group of consecutive glyph runs with the same face, size and
// colour (glyph meshes from the GlyphCache, as for one line in
// text_image.hpp), then the group's underline and strikethrough bars as one
// mesh.
// Geometry: the layout box's origin is at (margin, margin); the image is
// ceil(2 margin + box width) x ceil(2 margin + total line height), so the
// first baseline is at margin + A as in docs/design.md section 6.
#pragma once

#include "curvetext/export.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext {

// Background, antialiasing, curve test, vbaa filter, blending, gamma, debug
// view and transform: ImageStyle (image_style.hpp), as for single lines. The
// transform is applied about the centre of the untransformed image, which
// then grows to the transformed bounding box; `auto` picks per glyph run from
// its pixels per em on screen, as render_text_image does for a line.
struct ParagraphImageOptions : ImageStyle {
  double margin_px = 16.0;  // px, on every side
};

struct ImageSize {
  int width = 0, height = 0;  // px
};

// The image's size (after options.transform); no GL, thread-safe. Throws
// Error(InvalidArgument) for a bad margin, when a side would exceed
// tolerance::kMaxImageSidePx, or for a transform that transform_frame
// refuses.
CURVETEXT_API ImageSize paragraph_image_size(const Paragraph& paragraph, const ParagraphImageOptions& options);

// The untransformed image (margins around the layout box) under
// options.transform; same errors.
CURVETEXT_API ImageFrame paragraph_image_frame(const Paragraph& paragraph, const ParagraphImageOptions& options);

// Draws into an offscreen ImageTarget (at the frame's
// size) with glyph meshes from `cache`, and returns it read back. Needs the
// renderer's GL context current on the calling thread, and `cache` used with
// that context. Throws the errors of paragraph_image_frame, draw_options
// (gamma), DrawBatch's builders and the Renderer.
CURVETEXT_API Image render_paragraph_image(Renderer& renderer, GlyphCache& cache, const Paragraph& paragraph,
                                           const ParagraphImageOptions& options);

}  // namespace curvetext
