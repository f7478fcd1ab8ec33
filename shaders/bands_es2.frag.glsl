// One pass exact area on OpenGL ES 2.0 (docs/design.md section 9), fragment
// stage: compiled after bands.frag.glsl with CURVETEXT_ES2 1, whose area
// functions (crossing, arc_x_dy, piece_area) it shares; what GLSL ES 3.00
// does there with texelFetch, integers and bits is done here in highp
// floats. Indices are integers below 2^24 (a page holds 2^20 texels), exact
// in a float; texels are read by texture2D at their centres from a
// NEAREST-sampled float texture. The loop over a band's entries has the
// constant bound CURVETEXT_ES2_ENTRY_CAP (GLSL ES 1.00 Appendix A): glyphs
// with longer bands take the mesh path (lib/gpu/batch.cpp). It runs the exact
// area over the pieces across the box that a cheaper pass marked, as there.

uniform float u_rows;  // the page's rows (its width is CURVETEXT_BAND_WIDTH)

varying vec2 v_local;
varying vec4 v_rect;
varying vec2 v_glyph;

const float kWidth = float(CURVETEXT_BAND_WIDTH);
const int kRun = 16;  // entries a run (CURVETEXT_ES2_ENTRY_CAP is a multiple)

// Texel i of the page, i an integer: row and column exactly (the width is a
// power of two), sampled at the texel's centre.
vec4 texel_at(float i) {
  float row = floor(i / kWidth);
  return texture2D(u_bands, vec2((i - row * kWidth + 0.5) / kWidth, (row + 0.5) / u_rows));
}

// Component k (0 .. 3) of v.
float component(vec4 v, float k) {
  return k < 1.5 ? (k < 0.5 ? v.x : v.y) : (k < 2.5 ? v.z : v.w);
}

// An integer's bits from `shift` (a power of two) up, two of them: the
// floor stays exact for bits below 2^16 however exp2 rounds.
float two_bits(float bits, float shift) {
  return mod(floor((bits + 0.5) / shift), 4.0);
}

// 2^k for an integer k, exactly.
float power_of_two(float k) {
  return floor(exp2(k) + 0.5);
}

// bands.frag.glsl's block_state in floats.
float block_state_es2(float base, float n, float column, float row) {
  if (column < 0.0 || row < 0.0 || column > n || row > n) return 0.0;
  float i = row * (n + 1.0) + column;
  float t = floor(i / 32.0);
  float bits = component(texel_at(base + t), mod(floor(i / 8.0), 4.0));
  return two_bits(bits, power_of_two(2.0 * mod(i, 8.0)));
}

// bands.frag.glsl's grid_state in floats.
float grid_state_es2(float first, float grid, float left, float row_lo) {
  if (grid == 0.0) return 2.0;
  float side = max(v_rect.z - v_rect.x, v_rect.w - v_rect.y);
  float ratio = side / (2.0 * max(u_half.x, u_half.y)) / 1.0001;
  if (!(ratio >= power_of_two(float(CURVETEXT_GRID_MIN_LOG2)))) return 2.0;
  float g = min(floor(log2(ratio)), float(CURVETEXT_GRID_MAX_LOG2));
  float n = power_of_two(g);
  float base = first + grid;
  for (int k = CURVETEXT_GRID_MIN_LOG2; k < CURVETEXT_GRID_MAX_LOG2; ++k) {
    if (float(k) >= g) break;
    float m = power_of_two(float(k)) + 1.0;
    base += floor((m * m + 31.0) / 32.0);
  }
  vec2 c0 = floor((vec2(left, row_lo) - v_rect.xy) * (n / side));
  return block_state_es2(base, n, c0.x + 1.0, c0.y + 1.0);
}

void main() {
  float first = floor(v_glyph.x + 0.5);
  float levels = floor(v_glyph.y + 0.5);
  float height = v_rect.w - v_rect.y;
  float ratio = height / (2.0 * u_half.y * 1.0001);
  float level = ratio >= 1.0 ? floor(log2(ratio)) : 0.0;
  level = clamp(level, 0.0, levels - 1.0);
  float n = power_of_two(level);
  float h = height / n;
  float row_lo = v_local.y - u_half.y;
  float row_hi = v_local.y + u_half.y;
  float left = v_local.x - u_half.x;
  float right = v_local.x + u_half.x;
  float k = clamp(floor((row_lo - v_rect.y) / h), 0.0, n - 1.0);
  float band = n - 1.0 + k;
  vec4 regions = texel_at(first);  // (first entry texel, first reference texel, first cell texel)
  float entry_texel = first + regions.x;
  float ref_texel = first + regions.y;
  float pair = floor(band / 2.0);
  vec4 header = texel_at(first + 1.0 + pair);
  vec2 entries = band - 2.0 * pair < 0.5 ? header.xy : header.zw;
  float start = entries.x;
  float count = entries.y;
  vec2 scale = 0.5 / u_half;
  float sum = 0.0;
  float state = grid_state_es2(first, regions.z, left, row_lo);
  if (state != 2.0) {
    sum = state;
    count = 0.0;
  }
  // As bands.frag.glsl's loop: runs of entries, a cheap pass that sums the
  // pieces wholly right of the box and marks those across it (a bit set in
  // a float: integers below 2^24 are exact), then the exact area over the
  // marked ones, highest bit first.
  for (int r = 0; r < CURVETEXT_ES2_ENTRY_CAP / kRun; ++r) {
    float run = float(r * kRun);
    if (run >= count) break;
    float marked = 0.0;
    float bit = 1.0;
    bool done = false;
    for (int i = 0; i < kRun; ++i) {
      float value = bit;
      bit *= 2.0;
      if (run + float(i) >= count) break;
      vec4 e = texel_at(entry_texel + start + run + float(i));  // (largest x, smallest x, y of p0, y of p2)
      if (e.x < left) {
        done = true;
        break;
      }
      if (max(e.z, e.w) < row_lo || min(e.z, e.w) > row_hi) continue;
      if (e.y >= right) {
        // Wholly right of the box: its height within the rows (monotone in y).
        sum += clamp((e.w - v_local.y) * scale.y, -0.5, 0.5) - clamp((e.z - v_local.y) * scale.y, -0.5, 0.5);
      } else {
        marked += value;
      }
    }
    for (int m = 0; m < kRun; ++m) {
      if (marked == 0.0) break;
      // The highest bit, log2 corrected where it rounds across a power of two.
      float b = floor(log2(marked));
      float p = power_of_two(b);
      if (p > marked) {
        b -= 1.0;
        p *= 0.5;
      } else if (2.0 * p <= marked) {
        b += 1.0;
        p *= 2.0;
      }
      marked -= p;
      float j = start + run + b;
      float quad = floor(j / 4.0);
      float piece = first + component(texel_at(ref_texel + quad), j - 4.0 * quad);
      vec4 a = texel_at(piece);
      vec4 c = texel_at(piece + 1.0);
      sum += piece_area((a.xy - v_local) * scale, (a.zw - v_local) * scale, (c.xy - v_local) * scale, c.z);
    }
    if (done) break;
  }
  float coverage = clamp(sum, 0.0, 1.0);
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  gl_FragColor = u_color * coverage;
}
