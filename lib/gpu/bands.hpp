// Per-glyph curve bands (docs/design.md section 9): the boundary of a
// glyph's nonzero union as pieces monotone in x and y, listed per horizontal
// band at several levels, packed as RGBA float texels for
// shaders/bands.frag.glsl; and the exact area of a pixel box inside the
// glyph computed from them on the CPU, the shader's reference. Private to
// the library; tests include it.
//
// Texel layout of one glyph, from its first texel (RGBA32F, a row-major
// texture kBandTextureWidth texels wide; offsets relative to that texel):
//   texel 0: (first entry texel E, first reference texel R, first cell
//            texel G, 0); G = 0: no cell grids.
//   headers: band b (level L, band k: b = 2^L - 1 + k, L = 0..levels-1) in
//            texel 1 + b / 2, components 2 (b % 2) and 2 (b % 2) + 1: (its
//            first entry j, relative to E, and its entry count).
//   pieces:  two texels, (x0, y0, cx, cy), (x2, y2, w, line): the rational
//            quadratic (p0, c, p2) with end weights 1 and middle weight w, in
//            the outline's units, directed with the fill on its left (y up).
//            A line is stored as the conic whose control point is its
//            midpoint, w = 1 (its segment area is 0), with line = 1 (0
//            for a conic; the shader reads both through one path).
//   entries: texel E + j, one per piece in a band: (largest x, smallest x,
//            y of p0, y of p2), a band's entries by decreasing largest x, so
//            the loop over them stops at the first entry wholly left of the
//            pixel (such pieces add nothing, below); a piece wholly right of
//            it adds its height within the rows, read from the entry alone.
//   refs:    entry j's piece texel in component j % 4 of texel R + j / 4.
//   cells:   grids of n x n square cells (n = 2^g, g = kGridMinLog2 ..
//            kGridMaxLog2) over the square of the box's larger side from its
//            lower left corner, each cell 0 (wholly outside the glyph), 1
//            (wholly inside) or 2 (a piece reaches it); stored per block of
//            2 x 2 cells, (column - 1 .. column, row - 1 .. row), column and
//            row 0 .. n: 0 or 1 where all four are, else 2, in 2 bits. Block
//            i = row (n + 1) + column of grid g, from texel G plus the
//            coarser grids' ceil((n + 1)^2 / 32) texels each: bits 2 (i % 8)
//            of component (i / 8) % 4 of texel i / 32. A pixel box no larger
//            than a cell lies within one block: where the block is 0 or 1
//            that is its coverage, exactly, without the loop over its band
//            (most pixels of a large glyph), from one texel.
// Level L has 2^L bands; with H = (box height) / 2^L, band k holds the pieces
// that reach into [y0 + k H, y0 + (k + 2) H]: overlapping bands, so a pixel
// row at most H tall lies wholly in band floor((row's bottom - y0) / H).
//
// The area (Green's theorem): the part of the box [-1/2, 1/2]^2 (pixel units
// from its centre) inside a region whose boundary runs counter-clockwise is
// the sum over the boundary pieces of the integral of clamp(x + 1/2, 0, 1) dy
// over the part of each piece within the box's rows: a piece wholly left of
// the box adds nothing, one wholly right its height within the rows, one
// across the box the integral of (x + 1/2) dy over its part between the box's
// columns, in closed form for a conic (chord plus segment area), and its
// height right of them.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "curvetext/geometry.hpp"
#include "curvetext/mesh.hpp"

namespace curvetext::gpu {

// A rational quadratic piece with end weights 1 (see above).
struct BandPiece {
  Vec2 p0, c, p2;
  double w = 1.0;
};

// Appends `piece` split where x or y turns (one turn per coordinate at most:
// the arc stays in its control triangle and turns by less than half a turn),
// each part monotone in x and y.
void split_monotone(const BandPiece& piece, std::vector<BandPiece>& out);
// The oriented boundary pieces of `mesh` (its straight boundary and its
// curved triangles' arcs, fill on the left), split where x or y turns, into
// `out` (replaced).
void boundary_pieces(const Mesh& mesh, std::vector<BandPiece>& out);

// Width of the band texture in texels (a power of two the shader's
// addressing assumes).
inline constexpr int kBandTextureWidthLog2 = 10;
inline constexpr int kBandTextureWidth = 1 << kBandTextureWidthLog2;
// Most levels a glyph's bands have (2^kMaxBandLevels - 1 bands in all).
inline constexpr int kMaxBandLevels = 5;
// The cell grids: 8 x 8 and 16 x 16 cells (a pixel reads the finest whose
// cells are at least its size; 13 texels in all; a 32 x 32 grid doubled
// the grids' building time for a few per cent at 64 px, docs/performance.md).
inline constexpr int kGridMinLog2 = 3;
inline constexpr int kGridMaxLog2 = 4;

struct GlyphBands {
  std::vector<std::array<float, 4>> texels;
  Box box;              // of the pieces, in the float values the texels and instances carry
  int levels = 0;       // 0: nothing to draw
  bool conics = false;  // a piece has a middle weight other than 1 (the shader's CURVETEXT_CONICS)
  std::size_t pieces = 0, entries = 0;
  bool empty() const { return levels == 0; }
  std::size_t bytes() const { return texels.size() * sizeof(texels[0]); }
};

// Reused from glyph to glyph by a cache building many in a row.
struct BandScratch {
  std::vector<BandPiece> pieces;
  std::vector<std::uint32_t> order, refs, next;
  std::vector<std::array<float, 4>> entries;
  std::vector<std::uint8_t> cells;
  std::vector<int> delta;
};

void build_bands(const Mesh& mesh, GlyphBands& out, BandScratch& scratch);

// The integral of clamp(x + 1/2, 0, 1) dy over the part of `piece` (pixel
// units, from the box's centre) within rows [-1/2, 1/2]: any rational
// quadratic with positive weights (its parameter split at every crossing of
// the box's four lines).
double piece_box_integral(const BandPiece& piece);
// The same for a piece monotone in x and y, as the shader computes it (one
// crossing per line at most).
double monotone_piece_box_integral(const BandPiece& piece);
// The integral of x dy along the arc of `piece` between parameters t0 and t1:
// the chord's plus the signed area between arc and chord (closed form).
double arc_x_dy(const BandPiece& piece, double t0, double t1);
// The area between a conic arc of middle weight w and its chord over the area
// of its control triangle: 2/3 for a parabola, 0 as w -> 0, 1 as w -> inf.
double conic_segment_ratio(double w);

// The fraction of the box [centre - half, centre + half] (outline units,
// half > 0) that lies inside the region the pieces bound, through the
// general per-piece integral (every piece).
double box_coverage(std::span<const BandPiece> pieces, Vec2 centre, Vec2 half);
// The same through the packed bands, as the shader reads them: the level
// and band of the box's rows, the early stop, the culling by bounds.
double band_box_coverage(const GlyphBands& bands, Vec2 centre, Vec2 half);
// The level a box of half-height `half_y` reads (the shader's choice).
int band_level(const GlyphBands& bands, double half_y);
// The state of the cells under the box (0: all outside, 1: all inside, 2:
// the loop decides), as the shader reads them.
int grid_state(const GlyphBands& bands, Vec2 centre, Vec2 half);
// The state of the cells column - 1 .. column, row - 1 .. row of grid g
// together (0 or 1 where all four are, else 2; cells beyond the grid are 0),
// as packed.
int block_state(const GlyphBands& bands, int g, int column, int row);

// A pixel's footprint under a map that turns the axes (rotation, skew; the
// local affine map under perspective): the parallelogram {s u + r v :
// |s|, |r| <= 1/2} about the pixel's centre, u and v the images of the
// pixel's axes under the inverse map (the inverse Jacobian's columns), in
// the units of the pieces. Its area is |cross(u, v)|.
//
// The area of the region inside it is still integrated along the outline's
// x, as for the box, so the bands (by the parallelogram's y extent) and their
// culling (by its x extent) hold: the integrand is the width of its row left
// of the piece, clamp(x, xl(y), xr(y)) - xl(y), which is max(0, x - xl(y)) -
// max(0, x - xr(y)): a sum over its four edges of max(0, x - e(y)) over the
// edge's rows, plus for the left chain, minus for the right (each from the
// line's implicit form, no shear by the edge's slope). A piece wholly right of
// its x extent adds the width over its rows, one wholly left nothing.
struct Footprint {
  Vec2 u, v;
  // The half size of its bounding box.
  Vec2 half() const { return {0.5 * (std::abs(u.x) + std::abs(v.x)), 0.5 * (std::abs(u.y) + std::abs(v.y))}; }
  double area() const { return std::abs(cross(u, v)); }
};

// The integral of clamp(x, xl(y), xr(y)) - xl(y) dy over `piece` (units of
// `f`, from the parallelogram's centre): any rational quadratic with
// positive weights, cut at every height of a corner and every crossing of
// an edge's line, each part's row of the parallelogram from its midpoint.
double piece_footprint_integral(const BandPiece& piece, const Footprint& f);
// The same for a piece monotone in x and y, as the shader computes it: edge
// by edge, the parts of the piece right of the edge's line within its rows
// (two crossings at most).
double monotone_piece_footprint_integral(const BandPiece& piece, const Footprint& f);
// The part of a piece wholly right of the parallelogram between heights y0
// and y1 (from its centre): the integral of its row's width, per edge.
double footprint_width_integral(const Footprint& f, double y0, double y1);
// The fraction of the parallelogram about `centre` (outline units) inside
// the region the pieces bound: through every piece, and through the packed
// bands as the shader reads them (the band and the cells of its bounding
// box, the early stop, the culling by its x extent; the pieces scaled so that
// the bounding box is [-1/2, 1/2]^2, as the shader does).
double footprint_coverage(std::span<const BandPiece> pieces, Vec2 centre, const Footprint& f);
double band_footprint_coverage(const GlyphBands& bands, Vec2 centre, const Footprint& f);

}  // namespace curvetext::gpu
