// Private interface of core/ for every stage: the tolerances and work
// budgets of the library's inside, with their units. What a user can see
// (input limits, the curve bound, defaults of documented behaviour) is in the
// public curvetext/tolerances.hpp, which this header includes, so code that
// needs both includes this one.
#pragma once

#include <cstddef>

#include "curvetext/tolerances.hpp"

namespace curvetext::tolerance {

// --- Mesh building (lib/tessellate) -----------------------------------------
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
// Rounds in a row in which the crossing resolver cuts lines at new crossings
// before it stops with conflicts left (build_mesh then checks its mesh). Every
// glyph of the corpus and every fuzz corpus input settles within 3 (rounds).
inline constexpr int kMaxLineSplitRounds = 8;
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

// Work budget of one build_mesh call: hull separation may make at most this
// many pieces per piece of the cleaned outline (cubics already replaced), plus
// kMeshWorkBase, and the crossing resolver as many arrangement edges and as
// many cut points per round. Past it build_mesh throws Error(Geometry) instead
// of running on (every glyph of every face of the corpus fonts builds within
// it: docs/corpus.md). Dimensionless counts.
inline constexpr std::size_t kMeshWorkPerPiece = 64;
inline constexpr std::size_t kMeshWorkBase = 4096;
// Hull separation may test at most this many pairs of pieces whose boxes meet
// per (kMeshWorkPerPiece) unit of that budget, summed over its passes, plus
// kMeshPairTestsBase: a path that runs over itself n times has n^2 / 2 such
// pairs, and a short scribble of arcs and cubics crossing each other ~10^5
// (about 0.1 s for the base; dimensionless).
inline constexpr std::size_t kMeshPairTestsPerPiece = 1024;
inline constexpr std::size_t kMeshPairTestsBase = std::size_t{1} << 21;
// Cleaning looks for rings equal to each other (a path run over itself,
// fold_repeated_rings) only in outlines of at least this many pieces: below
// it hull separation's pairs among copies stay far within the budget, and a
// glyph pays nothing for the search (pieces).
inline constexpr std::size_t kFoldRingsMinPieces = 512;
// Ear clipping (the fallback where the sweep gives up) may look at most at
// n^2 + kEarClipVisitsPerVertex * n + kEarClipVisitsBase vertices over all its
// ear tests, n the polygon's vertices (dimensionless): each test looks at up
// to every vertex, so a clip that finds its ears as it goes fits, while a
// loop whose ears keep failing (about n^2.5 to n^3) stops with Error(Geometry).
inline constexpr std::size_t kEarClipVisitsPerVertex = 4096;
inline constexpr std::size_t kEarClipVisitsBase = std::size_t{1} << 24;

// --- Strokes (lib/stroke) ---------------------------------------------------
// A conic counts as a circular arc (its offsets then exact concentric arcs)
// when its legs' lengths and its weight match a circle's within this relative
// error (dimensionless; SVG arcs and round joins are within 1e-15).
inline constexpr double kStrokeCircleRelative = 1e-9;
// Points per fitted offset piece at which its distance to the true offset is
// measured, each way (the Hausdorff error is their largest; dimensionless).
inline constexpr int kStrokeFitSamples = 8;
// Deepest halving of a conic while fitting its offset (2^-20 of the conic):
// past it the last fit is kept (only a cusp of the offset gets there).
inline constexpr int kStrokeMaxFitDepth = 20;
// Offset fits (each measured at 2 x kStrokeFitSamples points by Newton's
// method, about 300 curve evaluations) one stroke may try: this many per
// segment of the path (lines and conics after cubics are split) plus a
// base; past it stroke_outline throws Error(Geometry). Smooth curves need
// 1-4 per side at 1/64 px (bench/stroke_bench); a tolerance near double
// precision needs 2^20 per conic (dimensionless counts).
inline constexpr std::size_t kStrokeFitsPerSegment = 64;
inline constexpr std::size_t kStrokeFitsBase = std::size_t{1} << 15;
// Segments shorter than this fraction of the path's largest |coordinate|
// count as zero length: they have no direction (dimensionless).
inline constexpr double kStrokeZeroLengthRelative = 1e-12;
// Path pieces, gaps between offset pieces and outline pieces shorter than
// this fraction of the stroke tolerance are dropped or closed (moving the
// boundary by at most that much): slivers of 1e-8 px, from cubics split near
// inflections and from the pivots of inner joins, only cost the mesher
// (dimensionless).
inline constexpr double kStrokeSnapOfTolerance = 1.0 / 1024.0;

// --- Text effects (lib/gpu/effects.cpp) ----------------------------------------
// A text outline's or centred stroke's offsets are fitted within this
// fraction of the glyph mesh's cubic tolerance (1/16 px at the top of its
// level of detail band: 1/64 px, the stroker's default; dimensionless).
inline constexpr double kEffectOffsetOfTolerance = 1.0 / 4.0;
// Where the mesher refuses the union of a wide stroke's loops with the glyph
// (its hull separation budget: round loops much larger than the glyph's
// curves), the loops and the glyph are flattened to lines within this
// fraction of that tolerance (1/256 px) and united again (dimensionless).
inline constexpr double kEffectFlatnessOfTolerance = 1.0 / 16.0;

// --- Rendering (lib/gpu, shaders/) -------------------------------------------
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

// The GLES 2 band program (shaders/bands_es2.frag.glsl) reads a band's
// entries in a loop of constant bound (GLSL ES 1.00 has no other): a glyph
// any of whose bands lists more entries than this (band 0 lists every piece
// of its boundary) takes the mesh path, and so does its whole block, on GLES 2
// only. In entries (boundary pieces); 35 of DejaVu Sans's 6,190 inked glyphs
// and none of Inter's exceed it; the loop stops early, so the bound costs
// only the glyphs that need it.
inline constexpr int kEs2BandEntryCap = 128;

}  // namespace curvetext::tolerance
