// One line of text to an image, following the geometry contract of docs/design.md
// section 6, so results can be compared with any other renderer:
//  - HarfBuzz shapes at `size_px` pixels per em; positions are not rounded;
//  - the pen starts at x = margin, the baseline is at y = margin + A, with A
//    and D the ascender and descender (hb_font_get_h_extents) in pixels;
//  - the image is ceil(2 margin + advance) x ceil(2 margin + A - D) pixels;
//  - pixel (i, j) covers [i, i+1] x [j, j+1], y grows downward.
#pragma once

#include <string_view>

#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext {

// Background, antialiasing, curve test, vbaa filter, blending, gamma, debug
// view and transform: ImageStyle (image_style.hpp), shared with paragraphs and
// shapes. The transform is applied about the centre of the contract's image;
// the image then becomes the bounding box of the transformed one (ceil of its
// size), so nothing is cut off. Identity: the contract exactly.
struct TextImageOptions : ImageStyle {
  double size_px = 32.0;         // pixels per em
  double margin_px = 16.0;       // px, on every side
  Color foreground{0, 0, 0, 1};  // straight alpha, sRGB
  ShapeOptions shaping;
};

struct TextImageLayout {
  ShapedLine line;               // font units
  int width = 0;                 // px, after the transform
  int height = 0;                // px
  Placement placement;           // font units -> image pixels, pen origin at (margin, margin + A)
                                 // (then placement.transform, identity unless options.transform is not)
  double largest_stretch = 1.0;  // of placement.transform over the image (for the level of detail)
  double ascender_px = 0.0;      // A, at size_px
  double descender_px = 0.0;     // D, negative below the baseline
};

// Shapes the text and sizes the image; no GL, thread-safe (font.hpp). Throws
// Error(InvalidText) for an empty text, invalid UTF-8, a text over
// tolerance::kMaxTextBytes or a grapheme cluster over
// tolerance::kMaxClusterCodePoints,
// Error(InvalidArgument) for a size <= 0, NaN or above
// tolerance::kMaxPixelsPerEm, a bad margin, an image side above
// tolerance::kMaxImageSidePx, a transform that transform_frame refuses, or
// the shaping options shape_line refuses.
CURVETEXT_API TextImageLayout layout_text_image(const Font& font, std::string_view text,
                                                const TextImageOptions& options);

// Draws the laid-out line with `renderer` into an offscreen ImageTarget
// (at the layout's size) with glyph meshes from `cache`, and
// returns it read back. Needs the renderer's GL context current on the
// calling thread, and `cache` used with that context. Throws the errors of
// draw_options, DrawBatch::from_text and the Renderer.
CURVETEXT_API Image render_text_image(Renderer& renderer, GlyphCache& cache, const Font& font,
                                      const TextImageLayout& layout, const TextImageOptions& options);

}  // namespace curvetext
