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

// The integral of x dy along the arc between t0 and t1: the chord's, plus
// the area between the sub-arc (its control point the blossom at (t0, t1))
// and its chord.
float arc_x_dy(vec2 p0, vec2 c, vec2 p2, float w, float t0, float t1) {
  vec3 h0 = conic_at(p0, c, p2, w, t0);
  vec3 h2 = conic_at(p0, c, p2, w, t1);
  float k0 = (1.0 - t0) * (1.0 - t1);
  float k1 = ((1.0 - t0) * t1 + t0 * (1.0 - t1)) * w;
  float k2 = t0 * t1;
  vec3 h1 = vec3(k0 * p0 + k1 * c + k2 * p2, k0 + k1 + k2);
#if CURVETEXT_CONICS
  vec2 a = h0.xy / h0.z;
  vec2 b = h2.xy / h2.z;
  vec2 m = h1.xy / h1.z - a;
  float ws = h1.z / sqrt(h0.z * h2.z);
#else
  vec2 a = h0.xy;
  vec2 b = h2.xy;
  vec2 m = h1.xy - a;
  float ws = 1.0;
#endif
  vec2 ab = b - a;
  return 0.5 * (a.x + b.x) * ab.y + segment_ratio(ws) * 0.5 * (m.x * ab.y - m.y * ab.x);
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

void main() {
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
