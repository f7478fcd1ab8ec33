// Curve shader, fragment stage of the single-pass modes: the paper's section
// 4, with the exact conic test of docs/design.md section 3. Interior triangles are
// solid; curved triangles test (none) or antialias (curves) their arc.
// Straight edges stay aliased. Full antialiasing is area.frag.glsl.
#extension GL_OES_standard_derivatives : enable
precision highp float;

uniform vec4 u_color;       // premultiplied
uniform int u_aa;           // 0 none, 1 curves
uniform int u_curve_mode;   // 0 exact, 1 paper
uniform float u_coverage_exponent;  // 1 / gamma (DrawOptions::gamma)
uniform int u_debug;        // 0 off, 1 discarded curve pixels shown, 2 triangle edges only (flat)

varying vec4 v_coef;
varying vec4 v_info;

// Signed distance in pixels to the exact conic F = tau1^2 - 4 w^2 tau0 tau2
// (positive on the filled side s), first order (the paper's).
float conic_distance(float t1, float t2, vec2 g1, vec2 g2, float w, float s) {
  float t0 = 1.0 - t1 - t2;
  vec2 g0 = -g1 - g2;
  float w4 = 4.0 * w * w;
  float f = t1 * t1 - w4 * t0 * t2;
  // Analytic gradient: dFdx(f) would be a finite difference of a quadratic.
  vec2 gf = 2.0 * t1 * g1 - w4 * (t2 * g0 + t0 * g2);
  float glen = length(gf);
  return glen > 1e-20 ? -s * f / glen : -s * f * 1e20;
}

void main() {
  if (u_debug == 2) {
    // Within a pixel of an edge: a barycentric over its screen gradient is
    // the distance to the edge where it is 0.
    float t1 = v_coef.x;
    float t2 = v_coef.y;
    float t0 = 1.0 - t1 - t2;
    float d = min(min(t0 / max(length(vec2(dFdx(t0), dFdy(t0))), 1e-20),
                      t1 / max(length(vec2(dFdx(t1), dFdy(t1))), 1e-20)),
                  t2 / max(length(vec2(dFdx(t2), dFdy(t2))), 1e-20));
    if (d > 1.0) discard;
    gl_FragColor = vec4(0.05, 0.35, 0.95, 1.0);
    return;
  }
  float kind = floor(v_info.x + 0.5);
  float coverage = 1.0;
  if (kind > 1.5) {
    float t1 = v_coef.x;
    float t2 = v_coef.y;
    float s = v_coef.z;
    float w = v_info.y;
    // tau is affine, so its screen derivatives are exact.
    vec2 g1 = vec2(dFdx(t1), dFdy(t1));
    vec2 g2 = vec2(dFdx(t2), dFdy(t2));
    float d;
    if (u_curve_mode == 0) {
      d = conic_distance(t1, t2, g1, g2, w, s);
    } else {
      // The paper's equation 2 with (u, v) = (tau1/2 + tau2, tau1/2), w0 = w2 = 1,
      // and its gradient by the chain rule (equation 3).
      float u = 0.5 * t1 + t2;
      float v = 0.5 * t1;
      vec2 gu = 0.5 * g1 + g2;
      vec2 gv = 0.5 * g1;
      float den = (2.0 - 2.0 * w) * u * u + 2.0 * (w - 1.0) * u + 1.0;
      den = (abs(den) < 1e-12) ? 1e-12 : den;
      float f = v - w * u * (1.0 - u) / den;
      vec2 gf = gv - w * (1.0 - 2.0 * u) / (den * den) * gu;
      float glen = length(gf);
      // Signed distance in pixels, positive on the filled side.
      d = (glen > 1e-20) ? -s * f / glen : -s * f * 1e20;
    }
    if (u_aa == 0) {
      coverage = d >= 0.0 ? 1.0 : 0.0;
    } else {
      coverage = clamp(0.5 + d, 0.0, 1.0);
    }
  }
  if (coverage <= 0.0) {
    // Debug (paper Figure 1): what a curved triangle throws away.
    if (u_debug == 1 && kind > 1.5) {
      gl_FragColor = vec4(1.0, 0.45, 0.0, 1.0);
      return;
    }
    discard;
  }
  gl_FragColor = u_color * (u_coverage_exponent == 1.0 ? coverage : pow(coverage, u_coverage_exponent));
}
