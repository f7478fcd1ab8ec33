// A laid-out paragraph (layout.hpp) to an image through the renderer: one
// DrawBatch per glyph run (glyph meshes from the GlyphCache, as for one line
// in text_image.hpp) plus underline and strikethrough bars as meshes.
// Geometry: the layout box's origin is at (margin, margin); the image is
// ceil(2 margin + box width) x ceil(2 margin + total line height), so the
// first baseline is at margin + A as in DESIGN.md section 6.
#pragma once

#include "curvetext/layout.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext {

struct ParagraphImageOptions {
  double margin_px = 16.0;
  Color background{1, 1, 1, 1};
  AntiAliasing antialiasing = AntiAliasing::Full;
  CurveMode curve_mode = CurveMode::Exact;
};

struct ImageSize {
  int width = 0, height = 0;
};

// Throws Error(InvalidArgument) when a side would exceed tolerance::kMaxImageSidePx.
ImageSize paragraph_image_size(const Paragraph& paragraph, const ParagraphImageOptions& options);

// Draws with `renderer` (its GL context current).
Image render_paragraph_image(Renderer& renderer, GlyphCache& cache, const Paragraph& paragraph,
                             const ParagraphImageOptions& options);

}  // namespace curvetext
