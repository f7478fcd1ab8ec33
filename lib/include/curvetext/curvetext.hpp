// All of curvetext's public API in one include. Where to start:
//   a paragraph in your own window       FontCollection + Paragraph::layout (layout.hpp), then
//                                        TextBlock (text_block.hpp) drawn by a Renderer (renderer.hpp)
//                                        in your render loop (README.md, examples/first_window)
//   one line you position glyph by glyph shape_line (shaping.hpp) -> DrawBatch (draw_batch.hpp)
//   a PNG without a window               HeadlessContext (headless.hpp) + render_text_image
//                                        (text_image.hpp) or render_paragraph_image (paragraph_image.hpp)
//   2D curved shapes, SVG icons          shapes.hpp (parse_svg, read_shape_file) -> ShapeDrawing
//                                        (shape_drawing.hpp) in your render loop, render_shape_image
//                                        (shape_image.hpp) for a PNG, or build_mesh (mesh.hpp)
//   strokes (lines with a width, dashes) stroke_outline (stroke.hpp) -> build_mesh, or a Shape's stroke
// Each header below is self-contained and may be included alone.
#pragma once

#include "curvetext/bidi.hpp"
#include "curvetext/color.hpp"
#include "curvetext/color_glyph.hpp"
#include "curvetext/curves.hpp"
#include "curvetext/default_font.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/error.hpp"
#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/geometry.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/line_break.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/markup.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_drawing.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/stroke.hpp"
#include "curvetext/stroke_style.hpp"
#include "curvetext/text_block.hpp"
#include "curvetext/text_effect_style.hpp"
#include "curvetext/text_effects.hpp"
#include "curvetext/text_image.hpp"
#include "curvetext/tolerances.hpp"
#include "curvetext/transform.hpp"
#include "curvetext/version.hpp"
