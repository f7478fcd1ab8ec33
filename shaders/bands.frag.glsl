// One pass exact area (docs/design.md section 9), fragment stage: the exact
// area of this pixel's box inside the glyph, from the boundary pieces of its
// nonzero union listed in the band that holds the box's rows (layout:
// lib/gpu/bands.hpp; the same computation on the CPU:
// monotone_piece_box_integral and band_box_coverage there, which the tests
// hold against exact coverage). Green's theorem: the box's area inside is the
// sum over the pieces of the integral of clamp(x + 1/2, 0, 1) dy over their
// parts within the box's rows (pixel units from its centre). A band's pieces
// come by decreasing largest x, so the loop stops at the first piece wholly
// left of the box: those add nothing; one wholly right adds its height
// within the rows, read from its entry alone.
#ifdef GL_ES
precision highp float;
precision highp int;
precision highp sampler2D;
#endif

uniform sampler2D u_bands;  // RGBA32F, CURVETEXT_BAND_WIDTH texels a row
uniform vec2 u_half;        // half a pixel's footprint along x and y, outline units
uniform vec4 u_color;       // premultiplied
uniform float u_coverage_exponent;  // 1 / gamma, in the program compiled with CURVETEXT_GAMMA 1

// GLSL ES 1.00 (CURVETEXT_ES2 1) shares the area functions below and reads
// the texels its own way (bands_es2.frag.glsl, appended).
#if !CURVETEXT_ES2
in vec2 v_local;
flat in vec4 v_rect;
flat in vec2 v_glyph;

out vec4 curvetext_color;

vec4 texel(int i) {
  return texelFetch(u_bands, ivec2(i & (CURVETEXT_BAND_WIDTH - 1), i >> CURVETEXT_BAND_WIDTH_LOG2), 0);
}
#endif

// The conic (p0, c, p2) with weights 1, w, 1 at t, homogeneous (x w, y w, w).
// Where a block's pieces are all parabolas (w = 1: every TrueType and CFF
// glyph) the program is compiled without CURVETEXT_CONICS, and the
// weights, divisions and the segment ratio's closed forms drop out: a
// software rasteriser runs both sides of a branch, so they would cost every
// piece.
vec3 conic_at(vec2 p0, vec2 c, vec2 p2, float w, float t) {
  float a = 1.0 - t;
  float b0 = a * a;
#if CURVETEXT_CONICS
  float b1 = 2.0 * t * a * w;
  float b2 = t * t;
  return vec3(b0 * p0 + b1 * c + b2 * p2, b0 + b1 + b2);
#else
  float b1 = 2.0 * t * a;
  return vec3(b0 * p0 + b1 * c + t * t * p2, 1.0);
#endif
}

float y_at(vec2 p0, vec2 c, vec2 p2, float w, float t) {
  vec3 h = conic_at(p0, c, p2, w, t);
#if CURVETEXT_CONICS
  return h.y / h.z;
#else
  return h.y;
#endif
}

// Where a coordinate (a0, a1, a2 at p0, c, p2), monotone along the piece,
// reaches `level`; the nearer end (0 or 1) where it does not. The roots of
// the Bernstein quadratic by the cancellation-free pair q / a, c / q.
float crossing(float a0, float a1, float a2, float w, float level) {
  float b0 = a0 - level;
  float b1 = w * (a1 - level);
  float b2 = a2 - level;
  bool increasing = a2 > a0;
  if (b0 >= 0.0 && b2 >= 0.0) return increasing ? 0.0 : 1.0;
  if (b0 <= 0.0 && b2 <= 0.0) return increasing ? 1.0 : 0.0;
  float a = b0 - 2.0 * b1 + b2;
  float b = b1 - b0;
  float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(max(b * b - a * b0, 0.0)));
  float r1 = a != 0.0 ? q / a : 2.0;
  float r2 = q != 0.0 ? b0 / q : r1;
  return clamp(r1 >= 0.0 && r1 <= 1.0 ? r1 : r2, 0.0, 1.0);
}

// The area between a conic arc of middle weight w and its chord over its
// control triangle's (a circle's or hyperbola's segment, affinely; the
// series in 1 - w near the parabola's 2/3, where the closed forms cancel).
float segment_ratio(float w) {
#if !CURVETEXT_CONICS
  return 2.0 / 3.0;
#else
  float e = 1.0 - w;
  if (abs(e) < 0.05) return 2.0 / 3.0 - e * (4.0 / 15.0 + e * (6.0 / 35.0 + e * (32.0 / 315.0 + e * 40.0 / 693.0)));
  if (w < 1.0) {
    float s = sqrt(e * (1.0 + w));
    return w * (acos(w) - w * s) / (s * s * s);
  }
  float s = sqrt((w - 1.0) * (w + 1.0));
  return w * (w * s - log(w + s)) / (s * s * s);
#endif
}

// The sub-arc between t0 and t1: its ends a, b, its control point (the
// blossom at (t0, t1)) less a, and its middle weight.
struct SubArc {
  vec2 a, b, m;
  float w;
};

SubArc sub_arc(vec2 p0, vec2 c, vec2 p2, float w, float t0, float t1) {
  vec3 h0 = conic_at(p0, c, p2, w, t0);
  vec3 h2 = conic_at(p0, c, p2, w, t1);
  float k0 = (1.0 - t0) * (1.0 - t1);
  float k1 = ((1.0 - t0) * t1 + t0 * (1.0 - t1)) * w;
  float k2 = t0 * t1;
  vec3 h1 = vec3(k0 * p0 + k1 * c + k2 * p2, k0 + k1 + k2);
#if CURVETEXT_CONICS
  vec2 a = h0.xy / h0.z;
  return SubArc(a, h2.xy / h2.z, h1.xy / h1.z - a, h1.z / sqrt(h0.z * h2.z));
#else
  return SubArc(h0.xy, h2.xy, h1.xy - h0.xy, 1.0);
#endif
}

// The integral of x dy along a sub-arc: its chord's, plus the area between
// it and its chord.
float chord_and_segment(SubArc s) {
  vec2 ab = s.b - s.a;
  return 0.5 * (s.a.x + s.b.x) * ab.y + segment_ratio(s.w) * 0.5 * (s.m.x * ab.y - s.m.y * ab.x);
}

// The integral of x dy along the arc between t0 and t1.
float arc_x_dy(vec2 p0, vec2 c, vec2 p2, float w, float t0, float t1) {
  return chord_and_segment(sub_arc(p0, c, p2, w, t0, t1));
}

// One piece monotone in x and y (pixel units from the box's centre): its
// height right of the box plus the integral of (x + 1/2) dy over its part
// across the box, both within the box's rows.
float piece_area(vec2 p0, vec2 c, vec2 p2, float w) {
  float ty0 = crossing(p0.y, c.y, p2.y, w, -0.5);
  float ty1 = crossing(p0.y, c.y, p2.y, w, 0.5);
  float lo = min(ty0, ty1);
  float hi = max(ty0, ty1);
  if (!(hi > lo)) return 0.0;
  float tx0 = clamp(crossing(p0.x, c.x, p2.x, w, -0.5), lo, hi);
  float tx1 = clamp(crossing(p0.x, c.x, p2.x, w, 0.5), lo, hi);
  bool increasing = p2.x > p0.x;
  float r0 = increasing ? tx1 : lo;
  float r1 = increasing ? hi : tx1;
  float sum = y_at(p0, c, p2, w, r1) - y_at(p0, c, p2, w, r0);
  float m0 = min(tx0, tx1);
  float m1 = max(tx0, tx1);
  if (m1 > m0) {
    sum += arc_x_dy(p0, c, p2, w, m0, m1) + 0.5 * (y_at(p0, c, p2, w, m1) - y_at(p0, c, p2, w, m0));
  }
  return sum;
}

#if !CURVETEXT_ES2
// The cells column - 1 .. column, row - 1 .. row of the n x n grid whose
// blocks start at texel `base`: 0 all wholly outside, 1 all wholly inside, 2
// otherwise (layout: lib/gpu/bands.hpp).
int block_state(int base, int n, int column, int row) {
  if (column < 0 || row < 0 || column > n || row > n) return 0;
  int i = row * (n + 1) + column;
  float bits = texel(base + (i >> 5))[(i >> 3) & 3];
  return (int(bits) >> (2 * (i & 7))) & 3;
}

// The cells under the pixel's box in the finest grid whose cells are at
// least the box: 0 all outside, 1 all inside (the coverage, exactly), 2
// otherwise (the loop decides).
int grid_state(int first, int grid, float left, float row_lo) {
  if (grid == 0) return 2;
  float side = max(v_rect.z - v_rect.x, v_rect.w - v_rect.y);  // the grids' square
  float ratio = side / (2.0 * max(u_half.x, u_half.y)) / 1.0001;
  if (!(ratio >= float(1 << CURVETEXT_GRID_MIN_LOG2))) return 2;
  int g = min(int(floor(log2(ratio))), CURVETEXT_GRID_MAX_LOG2);
  int n = 1 << g;
  int base = first + grid;
  for (int k = CURVETEXT_GRID_MIN_LOG2; k < g; ++k) base += (((1 << k) + 1) * ((1 << k) + 1) + 31) / 32;
  // The box's lower left cell; the box, no larger than a cell, lies in the
  // block of that cell and the three above and right of it.
  ivec2 c0 = ivec2(floor((vec2(left, row_lo) - v_rect.xy) * (float(n) / side)));
  return block_state(base, n, c0.x + 1, c0.y + 1);
}

#if CURVETEXT_FOOTPRINT
// Under a map that turns the axes (rotation, skew; perspective to first
// order, its local affine map at the pixel) the pixel's footprint in outline
// units is a parallelogram, integrated along the outline's x as the box is,
// so the bands and their culling hold (bands.hpp, Footprint; the CPU's
// monotone_piece_footprint_integral and band_footprint_coverage): the
// width of its row left of the piece is a sum over its four edges of
// max(0, x - e(y)) over the edge's rows, plus on the left chain, minus on the
// right. Units: from the pixel's centre, scaled so that the parallelogram's
// bounding box is [-1/2, 1/2]^2.
uniform mat3 u_transform;  // as the vertex stage's: its third row gives a projective map's w
uniform mat3 u_inverse;    // framebuffer pixels -> outline units (u_transform's inverse)
uniform int u_projective;  // 1: the footprint varies per pixel (no cells: u_half is not it)
flat in vec2 v_offset;     // the glyph's origin in the block, outline units

// The pixel's footprint at outline point p (block units): the columns of
// the inverse map's Jacobian, w (p's) times (g_i - p g_i.z) for columns g_i.
mat2 footprint_at(vec2 p) {
  float w = dot(vec3(u_transform[0].z, u_transform[1].z, u_transform[2].z), vec3(p, 1.0));
  return w * mat2(u_inverse[0].xy - p * u_inverse[0].z, u_inverse[1].xy - p * u_inverse[1].z);
}

// Positive right of the line through a along d (d.y != 0), as x - e(y).
float right_of(vec2 q, vec2 a, vec2 d) { return (d.y * (q.x - a.x) - d.x * (q.y - a.y)) * sign(d.y); }

// The edge's x at height y within its rows, from the parameter along it
// (a near-level edge is not sheared by its slope).
float edge_x(vec2 a, vec2 d, float y) { return a.x + d.x * clamp((y - a.y) / d.y, 0.0, 1.0); }

// The integral of x - e(y) dy along the arc between t0 and t1: arc_x_dy
// less the edge's chord over the same rows.
float beyond_edge(vec2 p0, vec2 c, vec2 p2, float w, float t0, float t1, vec2 a, vec2 d) {
  SubArc s = sub_arc(p0, c, p2, w, t0, t1);
  return chord_and_segment(s) - edge_x(a, d, 0.5 * (s.a.y + s.b.y)) * (s.b.y - s.a.y);
}

// Both roots of the Bernstein quadratic (b0, b1, b2), ascending; 2 for one
// that is not there (a line's second, or none).
vec2 bernstein_roots(float b0, float b1, float b2) {
  float a = b0 - 2.0 * b1 + b2;
  float b = b1 - b0;
  float disc = b * b - a * b0;
  if (disc < 0.0) return vec2(2.0);
  float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
  float r1 = a != 0.0 ? q / a : 2.0;
  float r2 = q != 0.0 ? b0 / q : r1;
  return vec2(min(r1, r2), max(r1, r2));
}

// Edge a -> b (counter-clockwise): the integral of max(0, x - e(y)) dy over
// the piece's part within the edge's rows (one parameter interval: the
// piece is monotone in y), plus on the left chain, minus on the right. Its
// line crossings cut it into a middle part on one side and outer parts on
// the other; the side is read at the middle of the longest part.
// s0 and s1: the piece's parameters at the heights of a and b; [m0, m1]
// its part within the bounding box's columns.
float edge_term(vec2 p0, vec2 c, vec2 p2, float w, vec2 a, vec2 b, float s0, float s1, float m0, float m1) {
  vec2 d = b - a;
  if (d.y == 0.0) return 0.0;
  float ta = max(min(s0, s1), m0);
  float tb = min(max(s0, s1), m1);
  if (!(tb > ta)) return 0.0;
  vec2 r = clamp(bernstein_roots(right_of(p0, a, d), w * right_of(c, a, d), right_of(p2, a, d)), ta, tb);
  float outer = max(r.x - ta, tb - r.y);
  bool middle_longest = r.y - r.x >= outer;
  float probe = middle_longest ? 0.5 * (r.x + r.y) : (r.x - ta >= tb - r.y ? 0.5 * (ta + r.x) : 0.5 * (r.y + tb));
  vec3 h = conic_at(p0, c, p2, w, probe);
  bool middle_right = (right_of(h.xy / h.z, a, d) > 0.0) == middle_longest;
  // One arc in all but the rare case of two crossings with the middle left
  // of the line (a SIMD group then skips the second).
  float sum = beyond_edge(p0, c, p2, w, middle_right ? r.x : ta, middle_right ? r.y : tb, a, d);
  if (!middle_right && r.y > r.x) sum -= beyond_edge(p0, c, p2, w, r.x, r.y, a, d);
  return a.y > b.y ? sum : -sum;
}

// A piece wholly right of the parallelogram, from height y0 to y1: the
// integral of its row's width; the chains' x cancel, leaving the edges'.
float width_integral(vec2 corner[4], float y0, float y1) {
  float sum = 0.0;
  for (int e = 0; e < 4; ++e) {
    vec2 a = corner[e];
    vec2 d = corner[(e + 1) & 3] - a;
    if (d.y == 0.0) continue;
    float c0 = clamp(y0, min(a.y, a.y + d.y), max(a.y, a.y + d.y));
    float c1 = clamp(y1, min(a.y, a.y + d.y), max(a.y, a.y + d.y));
    sum += sign(d.y) * (c1 - c0) * edge_x(a, d, 0.5 * (c0 + c1));
  }
  return sum;
}

// One piece across the parallelogram's x extent. Its part right of the
// bounding box is wholly right of the parallelogram (the width over its
// rows), its part left of it adds nothing, and the four edges' terms (the
// piece's parameters at the corners' heights shared between them) run over
// the part between, where x - e(y) stays within the box's width: a long
// flat piece reaching far right would otherwise enter as large terms of the
// two chains that cancel, and lose float precision.
float footprint_piece(vec2 p0, vec2 c, vec2 p2, float w, vec2 corner[4]) {
  float tx0 = crossing(p0.x, c.x, p2.x, w, -0.5);
  float tx1 = crossing(p0.x, c.x, p2.x, w, 0.5);
  bool increasing = p2.x > p0.x;
  float sum = width_integral(corner, y_at(p0, c, p2, w, increasing ? tx1 : 0.0),
                             y_at(p0, c, p2, w, increasing ? 1.0 : tx1));
  float m0 = min(tx0, tx1);
  float m1 = max(tx0, tx1);
  float s0 = crossing(p0.y, c.y, p2.y, w, corner[0].y);
  float s1 = crossing(p0.y, c.y, p2.y, w, corner[1].y);
  float s2 = crossing(p0.y, c.y, p2.y, w, corner[2].y);
  float s3 = crossing(p0.y, c.y, p2.y, w, corner[3].y);
  return sum + edge_term(p0, c, p2, w, corner[0], corner[1], s0, s1, m0, m1) +
         edge_term(p0, c, p2, w, corner[1], corner[2], s1, s2, m0, m1) +
         edge_term(p0, c, p2, w, corner[2], corner[3], s2, s3, m0, m1) +
         edge_term(p0, c, p2, w, corner[3], corner[0], s3, s0, m0, m1);
}

// The coverage of the pixel's parallelogram: the band of its bounding
// box's rows, the cells where the box lies in one block (an affine map:
// u_half is the box's half size), the loop's early stop by the box's left,
// and the entries in runs of 24 as in main(): a cheap pass adds the pieces
// wholly right and marks those across, the four edges' terms then run over
// the marked ones only.
float footprint_coverage() {
  int first = int(v_glyph.x);
  int levels = int(v_glyph.y);
  mat2 f = footprint_at(v_local + v_offset);
  vec2 half_box = u_projective != 0 ? 0.5 * (abs(f[0]) + abs(f[1])) : u_half;
  float height = v_rect.w - v_rect.y;
  float ratio = height / (2.0 * half_box.y * 1.0001);
  int level = clamp(ratio >= 1.0 ? int(floor(log2(ratio))) : 0, 0, levels - 1);
  int n = 1 << level;
  float row_lo = v_local.y - half_box.y;
  float row_hi = v_local.y + half_box.y;
  float left = v_local.x - half_box.x;
  float right = v_local.x + half_box.x;
  int band = n - 1 + clamp(int(floor((row_lo - v_rect.y) / (height / float(n)))), 0, n - 1);
  vec4 regions = texel(first);
  if (u_projective == 0) {
    int state = grid_state(first, int(regions.z), left, row_lo);
    if (state != 2) return float(state);
  }
  int entry_texel = first + int(regions.x);
  int ref_texel = first + int(regions.y);
  vec4 header = texel(first + 1 + band / 2);
  vec2 entries = (band & 1) == 0 ? header.xy : header.zw;
  vec2 scale = 0.5 / half_box;
  vec2 u = f[0] * scale;
  vec2 v = f[1] * scale;
  if (u.x * v.y - u.y * v.x < 0.0) {
    vec2 t = u;
    u = v;
    v = t;
  }
  vec2 corner[4] = vec2[4](-0.5 * (u + v), 0.5 * (u - v), 0.5 * (u + v), 0.5 * (v - u));
  float sum = 0.0;
  int start = int(entries.x);
  int end = start + int(entries.y);
  for (int run = start; run < end; run += 24) {
    uint marked = 0u;
    bool done = false;
    int stop = min(run + 24, end);
    for (int j = run; j < stop; ++j) {
      vec4 e = texel(entry_texel + j);  // (largest x, smallest x, y of p0, y of p2)
      if (e.x < left) {
        done = true;
        break;
      }
      if (max(e.z, e.w) < row_lo || min(e.z, e.w) > row_hi) continue;
      if (e.y >= right) {
        sum += width_integral(corner, (e.z - v_local.y) * scale.y, (e.w - v_local.y) * scale.y);
      } else {
        marked |= 1u << uint(j - run);
      }
    }
    while (marked != 0u) {
      uint lowest = marked & (~marked + 1u);
      marked ^= lowest;
      int j = run + int(round(log2(float(lowest))));
      int piece = first + int(texel(ref_texel + (j >> 2))[j & 3]);
      vec4 a = texel(piece);
      vec4 b = texel(piece + 1);
      sum += footprint_piece((a.xy - v_local) * scale, (a.zw - v_local) * scale, (b.xy - v_local) * scale, b.z, corner);
    }
    if (done) break;
  }
  return sum / abs(u.x * v.y - u.y * v.x);
}
#endif

// The pixel's colour from its coverage.
void shade(float sum) {
  float coverage = clamp(sum, 0.0, 1.0);
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  curvetext_color = u_color * coverage;
}

void main() {
#if CURVETEXT_FOOTPRINT
  shade(footprint_coverage());
  return;
#endif
  int first = int(v_glyph.x);
  int levels = int(v_glyph.y);
  // The finest level whose band height H holds the box's rows (H >= the
  // box's height), and the band from the rows' bottom.
  float height = v_rect.w - v_rect.y;
  float ratio = height / (2.0 * u_half.y * 1.0001);
  int level = ratio >= 1.0 ? int(floor(log2(ratio))) : 0;
  level = clamp(level, 0, levels - 1);
  int n = 1 << level;
  float h = height / float(n);
  float row_lo = v_local.y - u_half.y;
  float row_hi = v_local.y + u_half.y;
  float left = v_local.x - u_half.x;
  float right = v_local.x + u_half.x;
  int k = clamp(int(floor((row_lo - v_rect.y) / h)), 0, n - 1);
  int band = n - 1 + k;
  vec4 regions = texel(first);  // (first entry texel, first reference texel, first cell texel)
  int entry_texel = first + int(regions.x);
  int ref_texel = first + int(regions.y);
  vec4 header = texel(first + 1 + band / 2);
  vec2 entries = (band & 1) == 0 ? header.xy : header.zw;
  int start = int(entries.x);
  int count = int(entries.y);
  vec2 scale = 0.5 / u_half;
  float sum = 0.0;
  int state = grid_state(first, int(regions.z), left, row_lo);
  if (state != 2) {
    sum = float(state);
    count = 0;
  }
  // The entries in runs of 24: a cheap pass sums the pieces wholly right
  // of the box and marks those across it in a mask; the exact area then
  // runs over the marked ones only (about one per pixel), so lanes of a
  // SIMD group that wait for each other wait on the cheap pass.
  int end = start + count;
  for (int run = start; run < end; run += 24) {
    uint marked = 0u;
    bool done = false;
    int stop = min(run + 24, end);
    for (int j = run; j < stop; ++j) {
      vec4 e = texel(entry_texel + j);  // (largest x, smallest x, y of p0, y of p2)
      if (e.x < left) {
        done = true;
        break;
      }
      if (max(e.z, e.w) < row_lo || min(e.z, e.w) > row_hi) continue;
      if (e.y >= right) {
        // Wholly right of the box: its height within the rows (monotone in y).
        sum += clamp((e.w - v_local.y) * scale.y, -0.5, 0.5) - clamp((e.z - v_local.y) * scale.y, -0.5, 0.5);
      } else {
        marked |= 1u << uint(j - run);
      }
    }
    while (marked != 0u) {
      uint lowest = marked & (~marked + 1u);
      marked ^= lowest;
      int j = run + int(round(log2(float(lowest))));  // a power of two below 2^24: exact
      int piece = first + int(texel(ref_texel + (j >> 2))[j & 3]);
      vec4 a = texel(piece);
      vec4 b = texel(piece + 1);
      vec2 p0 = (a.xy - v_local) * scale;
      vec2 p2 = (b.xy - v_local) * scale;
      sum += piece_area(p0, (a.zw - v_local) * scale, p2, b.z);
    }
    if (done) break;
  }
  float coverage = clamp(sum, 0.0, 1.0);
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  curvetext_color = u_color * coverage;
}
#endif  // !CURVETEXT_ES2
