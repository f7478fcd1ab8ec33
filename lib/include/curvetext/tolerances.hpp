// The tolerances and limits a user of curvetext can observe, each with its
// unit: the bound on approximated curves, the input limits past which calls
// throw curvetext::Error (docs/limits.md), and the constants behind documented
// defaults. The library's inner tolerances and work budgets (merge distances,
// mesh-building budgets, offscreen tile sizes) are private, in
// lib/core/tolerances.hpp. Code refers to these names instead of writing
// numbers.
#pragma once

#include <cstddef>

namespace curvetext::tolerance {

// --- Curves -----------------------------------------------------------------
// Largest distance, in device pixels, allowed between a cubic and the
// quadratics that replace it (docs/design.md section 3: 1/16 px at every scale).
inline constexpr double kCubicApproximationPx = 1.0 / 16.0;
// Largest number of quadratics one cubic may become in cubic_to_quadratics
// (curves.hpp; guards against absurd scales; at this count the bound is still
// honoured for any glyph-sized cubic drawn below 10,000 px/em).
inline constexpr int kMaxQuadraticsPerCubic = 64;

// A shape contour whose end lies this close to its start, as a fraction of
// the tolerance fill_outline is given, is closed by moving its last point
// onto its start instead of by a line (dimensionless): files close subpaths
// a few 1e-6 short of where they began (rounded coordinates), and that
// hairpin line folding back over the first curve is invisible, but the
// mesher can refuse it.
// Only gaps below kCloseGapOfExtent of the contour's size are closed so: a
// contour that small is drawn as it is.
inline constexpr double kCloseGapOfTolerance = 0.25;
inline constexpr double kCloseGapOfExtent = 1e-4;

// --- Strokes (stroke.hpp) ------------------------------------------------------
// Largest distance, in device pixels, between a stroke's fitted offset conics
// and the true offset curve when a stroke is built for the scale it is drawn
// at (shape images); stroke_outline takes the tolerance in path units.
inline constexpr double kStrokeOffsetPx = 1.0 / 64.0;
// Dash ends lie within this fraction of the stroke tolerance of the arc
// length the dash pattern asks for (dimensionless; 1/16 of 1/64 px is about
// 1e-3 px).
inline constexpr double kStrokeDashLengthOfTolerance = 1.0 / 16.0;
// Most segments (lines and conics) one stroke may produce, over all its
// loops; past it stroke_outline throws Error(Geometry) (a pattern of 10^6
// dashes needs about 10^7). Meshing time and memory grow with the count.
inline constexpr std::size_t kMaxStrokeSegments = std::size_t{1} << 21;
// Smallest stroke tolerance, as a fraction of the path's largest |coordinate|
// plus the stroke's half width (dimensionless): below it double precision
// cannot measure the fit (about 4,000 ulps), and stroke_outline throws
// Error(InvalidArgument) instead of subdividing to its budget.
inline constexpr double kMinStrokeToleranceRelative = 1e-12;

// --- Text effects (text_effects.hpp) -----------------------------------------
// Widest text outline or centred stroke, in ems of the text's size: wider
// ones are refused (Error(InvalidArgument)); the glyph becomes a blob.
inline constexpr double kMaxTextEffectWidthEm = 1.0;
// Effect meshes are cached per width bucket: the width in ems rounded to a
// multiple of 1 / kTextEffectWidthStepsPerEm (0.0015 px at 100 px/em).
inline constexpr double kTextEffectWidthStepsPerEm = 65536.0;
// Largest shadow blur radius (px; sigma = blur / 2, the kernel reaching
// 3 sigma each side) and offset (px, each axis); larger ones are refused.
inline constexpr double kMaxShadowBlurPx = 128.0;
inline constexpr double kMaxShadowOffsetPx = 4096.0;

// --- Mesh input (build_mesh, mesh.hpp) ----------------------------------------
// Coordinates build_mesh accepts and how it reads them (outline units). Every
// product the exact predicates form must be a finite, normal double: incircle's
// fourth-degree terms reach (2 * kMaxMeshCoordinate)^4 = 1.6e121, far from
// overflow. A coordinate whose magnitude is below kFlushCoordinateRelative times
// the outline's largest |coordinate|, or below kFlushCoordinateAbsolute, is read
// as 0: it is below the rounding of any point the mesher computes from the
// largest one (at most 1/2048 of its ulp), and a subnormal or tiny value beside large
// ones makes the predicates' error terms underflow, which drove crossing
// resolution into endless splitting. Coordinates beyond kMaxMeshCoordinate get
// Error(Geometry).
inline constexpr double kMaxMeshCoordinate = 1e30;
inline constexpr double kFlushCoordinateRelative = 0x1p-64;
inline constexpr double kFlushCoordinateAbsolute = 1e-30;

// --- Rendering ----------------------------------------------------------------
// Farthest a vertex may lie from the origin of the coordinates it is drawn
// in, in pixels at the drawn scale: float32 on the GPU (24-bit significand)
// rounds positions below 2^20 px to within 1/16 px. Shape images draw their
// meshes relative to the view's centre and refuse geometry reaching further.
inline constexpr double kMaxGpuCoordinatePx = 1048576.0;
// `auto` antialiasing, for blocks the renderer does not draw from curve bands
// (shapes, GLES 2, ...), uses vbaa up to this many pixels per em (on screen)
// and full above it, from bench/quality_bench's table of the mesh path: vbaa has the lowest edge
// error (0.0009-0.0020) and largest error (0.021-0.043) of every mode at each
// measured size, 8 to 384 px (full: 0.0012-0.0058 and 0.041-0.074);
// above the largest size measured, full's edge error is already 0.0012 and
// vbaa's texture (16x the block's pixels) would grow with the square of the
// size. Past the GL texture limit vbaa degrades to a smaller factor or to
// full.
inline constexpr double kAutoVbaaMaxPx = 384.0;

// vbaa's "paper" filter (DrawOptions::vbaa_ring): horizontal and vertical
// neighbouring texels weighted 0.5, diagonal ones 0.25, against 1 under the
// pixel (dimensionless weights; bench/quality_bench rows vbaa-ringR).
inline constexpr float kVbaaPaperRing = 0.5f;

// Coverage gamma (DrawOptions::gamma, --gamma), dimensionless exponent
// 1/gamma applied to coverage in [0, 1]: limits of what is accepted.
inline constexpr double kMinCoverageGamma = 0.25;
inline constexpr double kMaxCoverageGamma = 4.0;

// --- Level of detail ---------------------------------------------------------
// Meshes of glyphs with cubics are built per power-of-two pixels-per-em band;
// the band's upper end is used to choose the cubic tolerance. The range of
// lod_for_scale (lod.hpp), as log2 of pixels per em.
inline constexpr int kMinLodLog2 = 3;   // 8 px/em and below share one mesh
inline constexpr int kMaxLodLog2 = 14;  // 16,384 px/em

// --- Synthetic bold and slant (Font::set_synthesis, docs/markup.md) ------------
// What a face lacking the weight or slant asked for gets, as fontconfig's
// 90-synthetic.conf and Pango do: outlines grown by 1/24 em (FreeType's
// FT_GlyphSlot_Embolden strength) and sheared by x += 0.2 y (em / em).
inline constexpr double kSyntheticEmboldenEm = 1.0 / 24.0;
inline constexpr double kSyntheticSlant = 0.2;
// Largest synthesis a Font accepts: growth in em, |shear| (dimensionless).
// Beyond them glyphs smear into their neighbours or lie nearly flat.
inline constexpr double kMaxSyntheticEmboldenEm = 0.25;
inline constexpr double kMaxSyntheticSlant = 1.0;

// --- Input limits (bad input gets an error, not a hang) -----------------------
inline constexpr double kMaxPixelsPerEm = 20000.0;
inline constexpr double kMaxImageSidePx = 16384.0;
// Largest absolute entry of a Transform matrix (pixels per pixel, or pixels
// for the translation column). Beyond it float precision on the GPU is gone.
inline constexpr double kMaxTransformEntry = 1e6;
// A transform whose determinant is below this fraction of (largest entry)^3
// (dimensionless) is singular: it squashes the text to a line.
inline constexpr double kMinTransformDeterminant = 1e-9;
// Every corner of a transformed image must keep a homogeneous w above this
// (dimensionless, w = 1 without perspective): w <= 0 is behind the viewer,
// and near 0 the projection explodes.
inline constexpr double kMinPerspectiveW = 1e-3;
// A transformed image must stay at least this thick, in pixels (its area
// over its longest side), unless it was no thicker than twice this before: a
// plane seen almost edge-on (--perspective 89.99) or a tiny scale squashes
// the content into a sliver of pixels, an image that looks empty.
// Error(InvalidArgument).
inline constexpr double kMinTransformedImagePx = 4.0;

// --- Input sizes (docs/limits.md lists these with the error each raises) -----
// Text of one Paragraph::layout call, one markup document and one
// --text-file, in UTF-8 bytes. Layout holds about 75 bytes per byte of text
// (code points, offsets, styles, glyphs), so 4 MiB (a long novel) costs
// about 300 MB. Error(InvalidText).
inline constexpr std::size_t kMaxTextBytes = std::size_t{4} << 20;
// Code points in one grapheme cluster (a letter and its combining marks).
// HarfBuzz attaches each mark by looking back over the marks before it, so a
// cluster costs the square of its length; Unicode's stream-safe format
// (UAX #15) allows 30 marks in a row, and stacked-mark text stays far below
// this. Error(InvalidText).
inline constexpr std::size_t kMaxClusterCodePoints = 256;
// Styled spans of one paragraph (TextSpan) and markup spans. Error(InvalidArgument)
// from Paragraph::layout, Error(InvalidText) from parse_markup.
inline constexpr std::size_t kMaxSpans = std::size_t{1} << 18;
// Elements open at once in markup (<b><i>...). Error(InvalidText).
inline constexpr std::size_t kMaxMarkupDepth = 64;
// Shape documents (SVG, JSON): bytes of one file, segments (line, curve or
// arc piece) of one path or shape, and of the whole document. Meshing time
// and memory grow with the segment count. Error(InvalidArgument), Error(Io)
// for a file over the size.
inline constexpr std::size_t kMaxShapeFileBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxSegmentsPerPath = std::size_t{1} << 16;
inline constexpr std::size_t kMaxSegmentsPerDocument = std::size_t{1} << 18;
// Shape groups (ShapeGroup: group opacity, clip paths) nested deeper than
// this are refused: each open group holds an offscreen layer the size of
// the viewport (and a clip one more while its mask is drawn).
inline constexpr std::size_t kMaxShapeGroupDepth = 32;
// More shape groups than this in one document are refused: each is an
// offscreen pass over the whole viewport per draw (markers clipped by their
// viewport on a path of many vertices make one each).
inline constexpr std::size_t kMaxShapeGroups = 4096;

// --- Colour glyphs (color_glyph.hpp) -------------------------------------------
// A COLR v1 paint graph nested deeper than this (paints within paints,
// colour glyphs referring to colour glyphs) is refused: fonts are untrusted
// and a cycle would never end.
inline constexpr int kMaxColorPaintDepth = 32;
// Most layers one colour glyph may have (each is drawn as a pass of its own),
// and most paints a COLR v1 glyph's graph may visit to find them.
inline constexpr std::size_t kMaxColorLayers = 1024;
inline constexpr std::size_t kMaxColorPaints = 16384;
// Largest side of a colour bitmap, in pixels (CBDT / sbix strikes are at
// most a few hundred; RGBA8: 4 MiB at this side).
inline constexpr int kMaxColorBitmapSidePx = 1024;
// Side of a page of the colour bitmap atlas, in texels (RGBA8: 4 MiB). A
// bitmap and its levels are stored with a border of transparent texels, so
// linear filtering never reads a neighbour.
inline constexpr int kColorAtlasPageTexels = 1024;

}  // namespace curvetext::tolerance
