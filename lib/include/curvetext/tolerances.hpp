// Every tolerance curvetext uses, in one place, with its unit. Code elsewhere
// refers to these names instead of writing numbers.
#pragma once

#include <cstddef>

namespace curvetext::tolerance {

// --- Curves -----------------------------------------------------------------
// Largest distance, in device pixels, allowed between a cubic and the
// quadratics that replace it (DESIGN.md section 3: 1/16 px at every scale).
inline constexpr double kCubicApproximationPx = 1.0 / 16.0;
// Largest number of quadratics one cubic may become (guards against absurd
// scales; at this count the bound is still honoured for any glyph-sized cubic
// drawn below 10,000 px/em).
inline constexpr int kMaxQuadraticsPerCubic = 64;

// --- Tessellation -------------------------------------------------------------
// Relative area error allowed by the area identity check (mesh vs outline).
inline constexpr double kAreaIdentityRelative = 1e-6;
// Floor of the area the identity's error is relative to, as a fraction of the
// squared diagonal of the outline's control box (dimensionless). Outlines
// whose nonzero area is zero (contours that cancel, back-and-forth lines)
// have reference areas of rounding noise (~1e-16 of diag^2) otherwise
// compared relatively to nothing.
inline constexpr double kAreaIdentityFloorOfBox = 1e-6;
// Deepest de Casteljau subdivision used to separate overlapping curve hulls.
inline constexpr int kMaxHullSubdivisionDepth = 10;
// Points closer than this fraction of the outline's largest |coordinate| are
// merged when building loops (dimensionless; 1e-9 font units for a glyph whose
// coordinates reach 1000). Relative, so that an outline drawn in tiny units
// (a triangle of side 1e-9) keeps its pieces.
inline constexpr double kMergeDistanceRelative = 1e-12;
// A conic whose control point lies closer to its chord's line than this
// fraction of the chord length is treated as a straight line (dimensionless;
// the area this ignores is below 1e-9 of the chord length squared). Also the
// tolerance for recognising a two-line spike that folds back on itself.
inline constexpr double kConicFlatnessRelative = 1e-9;

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
// Work budget of one build_mesh call: hull separation may make at most this
// many pieces per piece of the cleaned outline (cubics already replaced), plus
// kMeshWorkBase, and the crossing resolver as many arrangement edges and as
// many cut points per round. Past it build_mesh throws Error(Geometry) instead
// of running on (every glyph of every face of the corpus fonts builds within
// it: docs/corpus.md). Dimensionless counts.
inline constexpr std::size_t kMeshWorkPerPiece = 64;
inline constexpr std::size_t kMeshWorkBase = 4096;
// Hull separation may test at most this many pairs of pieces whose boxes meet
// per (kMeshWorkPerPiece) unit of that budget, summed over its passes: a path
// that runs over itself n times has n^2 / 2 such pairs (dimensionless).
inline constexpr std::size_t kMeshPairTestsPerPiece = 1024;
// Ear clipping (the fallback where the sweep gives up) may look at most at
// n^2 + kEarClipVisitsPerVertex * n + kEarClipVisitsBase vertices over all its
// ear tests, n the polygon's vertices (dimensionless): each test looks at up
// to every vertex, so a clip that finds its ears as it goes fits, while a
// loop whose ears keep failing (about n^2.5 to n^3) stops with Error(Geometry).
inline constexpr std::size_t kEarClipVisitsPerVertex = 4096;
inline constexpr std::size_t kEarClipVisitsBase = std::size_t{1} << 24;

// --- Rendering ----------------------------------------------------------------
// Farthest a vertex may lie from the origin of the coordinates it is drawn
// in, in pixels at the drawn scale: float32 on the GPU (24-bit significand)
// rounds positions below 2^20 px to within 1/16 px. Shape images draw their
// meshes relative to the view's centre and refuse geometry reaching further.
inline constexpr double kMaxGpuCoordinatePx = 1048576.0;
// How far every triangle grows outward for `full` antialiasing (and vbaa's
// offscreen pass), in pixels: a pixel's box reaches at most sqrt(2)/2 px
// from its centre, so every pixel that overlaps a triangle gets a fragment of
// it (shaders/area.frag.glsl). Also the shaders' CURVETEXT_PIXEL_REACH_PX.
inline constexpr float kFringeWidthPx = 0.7072f;

// Growing a triangle (lib/gpu/pack.cpp): where 1 + cos(angle between the two
// edges' outward normals) is below this, the miter would reach more than
// 1 / sqrt(this / 2) = 4 times the growth past the vertex (a corner sharper
// than about 29 degrees), and the corner is bevelled instead. Dimensionless.
inline constexpr double kMinMiterDenominator = 0.125;

// Full antialiasing (shaders/area.frag.glsl) finds a triangle's part of a
// pixel from its barycentrics' screen gradients, and a curved triangle's
// control points by inverting them. For a triangle thinner than this (its
// smallest altitude, in pixels) the gradients are huge and nearly parallel,
// and both lose their digits (seen: 0.2-0.3 of coverage in empty pixels next
// to a flat piece of a cubic), so it counts as empty instead: it lies within
// this distance of a line, so it held at most sqrt(2) times this of any pixel
// (0.0055). Also the shaders' CURVETEXT_THIN_TRIANGLE_PX.
inline constexpr float kThinTrianglePx = 1.0f / 256.0f;

// Border around a block's projected bounding box in the vbaa / msaa offscreen
// pass, in pixels: the triangles' growth (kFringeWidthPx) plus the filter's ring
// of one texel, rounded up.
inline constexpr double kOffscreenBorderPx = 2.0;

// Offscreen coverage textures of full / vbaa antialiasing (lib/gpu/renderer.cpp):
// at most kCoverageTileTexels per side (RGBA8: 16 MiB), a larger block drawn
// tile by tile; up to kCoverageSlots of them keep their passes for reuse, as
// long as they hold at most kCoverageBudgetBytes together (past that the least
// recently used one is redrawn). msaa's multisampled renderbuffer: at most
// kMsaaTileTexels per side (4 samples: 16 MiB).
inline constexpr int kCoverageTileTexels = 2048;
inline constexpr std::size_t kCoverageSlots = 8;
inline constexpr std::size_t kCoverageBudgetBytes = std::size_t{48} << 20;
inline constexpr int kMsaaTileTexels = 1024;

// `auto` antialiasing uses vbaa up to this many pixels per em (on screen) and
// full above it, from bench/quality_bench's table: vbaa has the lowest edge
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
// the band's upper end is used to choose the cubic tolerance.
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
