// Curve shader, fragment stage: coverage of solid, edge and curved triangles
// (paper section 4 with the exact conic test of DESIGN.md section 3).
#extension GL_OES_standard_derivatives : enable
precision highp float;

uniform vec4 u_color;       // premultiplied
uniform int u_aa;           // 0 none, 1 curves, 2 full
uniform int u_curve_mode;   // 0 exact, 1 paper

varying vec4 v_coef;
varying vec2 v_info;

// Exact area of the unit pixel square (centred on the fragment) on the inside
// of a straight edge at signed distance d (pixels, positive inside) with unit
// normal n. The projection of the square on n is the sum of two uniform
// variables of widths a = |n.x| and b = |n.y|; integrating its density gives
// the difference of ramps below.
float R(float x) { float y = max(x, 0.0); return y * y; }
float boxcov(float d, vec2 n) {
  float a = abs(n.x);
  float b = abs(n.y);
  float hi = 0.5 * (a + b);
  if (d >= hi) return 1.0;
  if (d <= -hi) return 0.0;
  float lo = max(a, b);
  float sm = min(a, b);
  // Nearly axis-aligned: the quadratic pieces shrink to nothing and the
  // formula would divide rounding noise by ~0; the limit is a linear ramp.
  if (sm < 1e-3) return clamp(0.5 + d / lo, 0.0, 1.0);
  float u = 0.5 * (a - b);
  return (R(d + hi) - R(d + u) - R(d - u) + R(d - hi)) / (2.0 * a * b);
}

// Coverage factor of one distance slot (outline units, affine).
float edge_factor(float c) {
  vec2 g = vec2(dFdx(c), dFdy(c));
  float len = length(g);
  // A constant slot (unused, 1e6) has no gradient: no edge here.
  if (len < 1e-12) return 1.0;
  return boxcov(c / len, g / len);
}

void main() {
  float kind = floor(v_info.x + 0.5);
  float coverage = 1.0;
  if (kind > 0.5 && kind < 1.5) {
    // Straight edges are antialiased only in full mode (the paper's single
    // pass leaves them aliased).
    if (u_aa == 2) {
      coverage = edge_factor(v_coef.x) * edge_factor(v_coef.y) * edge_factor(v_coef.z) *
                 edge_factor(v_coef.w);
    }
  } else if (kind > 1.5) {
    float t1 = v_coef.x;
    float t2 = v_coef.y;
    float s = v_coef.z;
    float w = v_info.y;
    // tau is affine, so its screen derivatives are exact.
    vec2 g1 = vec2(dFdx(t1), dFdy(t1));
    vec2 g2 = vec2(dFdx(t2), dFdy(t2));
    float f;
    vec2 gf;
    if (u_curve_mode == 0) {
      float t0 = 1.0 - t1 - t2;
      vec2 g0 = -g1 - g2;
      float w4 = 4.0 * w * w;
      // Beyond the chord (tau1 < 0, only reached by fringes) tau1^2 would
      // resurrect the mirror image of the curve; for concave curves that
      // region is outside, which tau1*|tau1| keeps (same value and gradient
      // at tau1 = 0).
      float q = (s < 0.0) ? t1 * abs(t1) : t1 * t1;
      vec2 gq = (s < 0.0) ? 2.0 * abs(t1) * g1 : 2.0 * t1 * g1;
      f = q - w4 * t0 * t2;
      // Analytic gradient: dFdx(f) would be a finite difference of a quadratic.
      gf = gq - w4 * (t2 * g0 + t0 * g2);
    } else {
      // The paper's equation 2 with (u, v) = (tau1/2 + tau2, tau1/2), w0 = w2 = 1,
      // and its gradient by the chain rule (equation 3).
      float u = 0.5 * t1 + t2;
      float v = 0.5 * t1;
      vec2 gu = 0.5 * g1 + g2;
      vec2 gv = 0.5 * g1;
      float den = (2.0 - 2.0 * w) * u * u + 2.0 * (w - 1.0) * u + 1.0;
      den = (abs(den) < 1e-12) ? 1e-12 : den;
      f = v - w * u * (1.0 - u) / den;
      gf = gv - w * (1.0 - 2.0 * u) / (den * den) * gu;
    }
    float glen = length(gf);
    // Signed distance in pixels, positive on the filled side.
    float d = (glen > 1e-20) ? -s * f / glen : -s * f * 1e20;
    if (u_aa == 0) {
      coverage = d >= 0.0 ? 1.0 : 0.0;
    } else if (u_aa == 1) {
      coverage = clamp(0.5 + d, 0.0, 1.0);
    } else {
      coverage = boxcov(d, (glen > 1e-20) ? gf / glen : vec2(1.0, 0.0));
    }
  }
  if (coverage <= 0.0) discard;
  gl_FragColor = u_color * coverage;
}
