// Curve shader, fragment stage: coverage of solid, edge and curved triangles
// (paper section 4 with the exact conic test of DESIGN.md section 3).
#extension GL_OES_standard_derivatives : enable
precision highp float;

uniform vec4 u_color;       // premultiplied
uniform int u_aa;           // 0 none, 1 curves, 2 full
uniform int u_curve_mode;   // 0 exact, 1 paper
uniform float u_coverage_exponent;  // 1 / gamma (DrawOptions::gamma)
uniform int u_debug;        // 0 off, 1 discarded curve pixels shown, 2 triangle edges (flat)

varying vec4 v_coef;
varying vec4 v_info;
varying vec3 v_tau;
varying vec2 v_fade;

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

// Coverage of the intersection of several boundaries, folded in one at a
// time: `cov` so far, `nacc` the sum of the inward normals folded so far.
// Independent (perpendicular) boundaries multiply; a boundary facing those
// already folded (a feature thinner than a pixel: both sides in one box)
// removes its outside area, a + b - 1, instead, as the product would count
// the overlap of the two outsides twice; in between, the two are mixed by
// the angle. A boundary nearly parallel to those folded (an obtuse corner,
// or two curves meeting smoothly, each of whose conics continues past the
// join along the other) cuts off mostly the same outside area: there the
// intersection tends to the smaller coverage, as the product would count
// that area twice. Boundaries that do not cut the box (coverage 1) are
// skipped so their normals do not count.
void fold(inout float cov, inout vec2 nacc, float a, vec2 n) {
  if (a >= 1.0) return;
  float nlen = length(nacc);
  float c = nlen > 1e-6 ? dot(nacc / nlen, n) : 0.0;
  float both = c < 0.0 ? mix(cov * a, max(cov + a - 1.0, 0.0), -c) : mix(cov * a, min(cov, a), c * c);
  cov = both;
  nacc += n;
}

// Folds in one distance slot (outline units, affine, positive inside).
void fold_line(inout float cov, inout vec2 nacc, float c) {
  vec2 g = vec2(dFdx(c), dFdy(c));
  float len = length(g);
  // A constant slot (unused, 1e6) has no gradient: no edge here.
  if (len < 1e-12) return;
  fold(cov, nacc, boxcov(c / len, g / len), g / len);
}

// Folds in the two sides of a reflex corner (the a_fade pair of an interior
// triangle flagged kUnionFadeFlag, see vertex_format.hpp): the shape there is
// the union of both half-planes, so the box's outside is the intersection of
// the two outsides, estimated as fold() estimates intersections; the union's
// normal for later folds is each side's, weighted by the outside it cuts off.
void fold_union(inout float cov, inout vec2 nacc, float c0, float c1) {
  vec2 g0 = vec2(dFdx(c0), dFdy(c0));
  vec2 g1 = vec2(dFdx(c1), dFdy(c1));
  float l0 = length(g0);
  float l1 = length(g1);
  if (l0 < 1e-12 || l1 < 1e-12) return;
  vec2 n0 = g0 / l0;
  vec2 n1 = g1 / l1;
  float o0 = 1.0 - boxcov(c0 / l0, n0);
  float o1 = 1.0 - boxcov(c1 / l1, n1);
  float o = o0;
  vec2 no = -n0;
  fold(o, no, o1, -n1);
  vec2 nb = o0 * n0 + o1 * n1;
  fold(cov, nacc, 1.0 - o, length(nb) > 1e-6 ? normalize(nb) : n0);
}

// Signed distance in pixels to the exact conic F = tau1^2 - 4 w^2 tau0 tau2
// (positive on the filled side s) and its unit normal towards the filled
// side. `mirror` replaces tau1^2 by tau1*|tau1| (see the curved triangles).
float conic_distance(float t1, float t2, vec2 g1, vec2 g2, float w, float s, bool mirror, bool second_order, out vec2 n) {
  float t0 = 1.0 - t1 - t2;
  vec2 g0 = -g1 - g2;
  float w4 = 4.0 * w * w;
  float q = mirror ? t1 * abs(t1) : t1 * t1;
  vec2 gq = mirror ? 2.0 * abs(t1) * g1 : 2.0 * t1 * g1;
  float f = q - w4 * t0 * t2;
  // Analytic gradient: dFdx(f) would be a finite difference of a quadratic.
  vec2 gf = gq - w4 * (t2 * g0 + t0 * g2);
  float glen = length(gf);
  if (glen <= 1e-20) {
    n = vec2(1.0, 0.0);
    return -s * f * 1e20;
  }
  vec2 m = gf / glen;
  n = -s * m;
  // The single-pass modes keep the paper's first-order distance.
  if (!second_order) return -s * f / glen;
  // f is quadratic, so along the gradient line f(x + t m) = f + glen t + q t^2
  // exactly, qq = m.H.m / 2; its root nearest t = 0 is the distance along
  // that line. f / glen alone halves the distance where the conic is nearly
  // a pair of lines (a flat hull: the arc and the parabola's other arm a
  // pixel apart), smearing coverage over twice the width. No root (negative
  // discriminant): the boundary is farther than first order says.
  float hq = mirror ? (t1 < 0.0 ? -1.0 : 1.0) : 1.0;
  float qq = hq * dot(g1, m) * dot(g1, m) - w4 * dot(g0, m) * dot(g2, m);
  float disc = max(glen * glen - 4.0 * f * qq, 0.0);
  return -s * 2.0 * f / (glen + sqrt(disc));
}

// Box coverage of the conic's filled side: the mean of nine third-pixel
// boxes' coverages, each against the conic's tangent line at that box. One
// tangent line for the whole pixel ignores the curvature, which at small sizes
// (radii of 1-3 px) biases every edge pixel of a convex contour heavy and of a
// concave one light by up to curvature/24; sub-boxes cut that ninefold.
// tau is affine, so its values at the sub-box centres are exact.
//
// `code` >= 0 names a hull edge (0 the chord, 1 / 2 the legs, as in
// fold_near_curve) beyond which the shape is solid (an interior triangle
// lies there): the fill is the union of that side and the conic's filled
// part, so each sub-box takes the larger of the two coverages (the union's
// is at least either). The conic alone is not enough there: its other arm
// (a flat hull with the control point near one end tilts a parabola's axis
// almost along the chord) or a hyperbola's second branch can pass within a
// pixel beyond the edge. Beyond a chord this holds only over the chord's
// span (code 3, the curved triangle and its fringes); past its ends the
// conic continues the outline smoothly, which is the better guess there (the
// union would overfill beyond the ends by the angle between chord and
// tangent). Interior triangles (codes 0-2) lie on the solid side everywhere,
// so they take the union throughout (with the span limit the far arm
// reappears just past the chord's ends). Legs are tangents (the conic stays
// on the hull's side). code < 0: the conic alone.
float conic_coverage(float t1, float t2, vec2 g1, vec2 g2, float w, float s, bool mirror, float code, out vec2 n) {
  bool chord = code < 0.5 || code > 2.5;
  vec2 ge = chord ? g1 : (code < 1.5 ? g2 : -g1 - g2);
  float ge_len = max(length(ge), 1e-30);
  float e = chord ? t1 : (code < 1.5 ? t2 : 1.0 - t1 - t2);
  vec2 ne = -ge / ge_len;  // towards the solid side
  float de = -e / ge_len;  // pixels, positive on the solid side
  // Position along the chord (0 at p0, 1 at p2): the combination of tau2 and
  // tau1 whose gradient is orthogonal to tau1's, the chord's normal.
  float k = -dot(g1, g2) / max(dot(g1, g1), 1e-30);
  float cov = 0.0;
  vec2 mom = vec2(0.0);  // first moment of the sub-box coverages
  vec2 nq;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      vec2 u = vec2(float(i) - 1.0, float(j) - 1.0) / 3.0;
      float u1 = t1 + dot(g1, u);
      float u2 = t2 + dot(g2, u);
      float dq = conic_distance(u1, u2, g1, g2, w, s, mirror, true, nq);
      float a = boxcov(3.0 * dq, nq);  // a third-pixel box: distances in its units
      float along = u2 + k * u1;
      bool in_span = code < 2.5 || (along >= 0.0 && along <= 1.0);
      if (code > -0.5 && in_span && a < 1.0) a = max(a, boxcov(3.0 * (de + dot(ne, u)), ne));
      cov += a;
      mom += a * u;
    }
  }
  conic_distance(t1, t2, g1, g2, w, s, mirror, true, n);
  // The conic's gradient at the pixel centre is the boundary's normal only
  // near the arc. Where the centre lies past the conic's other arm (a flat
  // hull whose parabola opens along its chord) or the coverage came from the
  // solid side of a hull edge, it can point away from the filled side, and
  // fold() would take this curve and a neighbour continuing it smoothly for
  // the two sides of a hairline. The first moment of the sub-box coverages
  // points towards the filled side; when the two disagree, trust it.
  if (dot(n, mom) < 0.0 && dot(mom, mom) > 1e-8) n = normalize(mom);
  return cov / 9.0;
}

// A lower bound on the distance in pixels from the fragment to a curve's
// control triangle (which holds the arc): how far it lies past the hull's
// ends along the chord. The hull lies within the slab of positions along the
// chord between its vertices' (0 at p0, 1 at p2, k at the control point);
// "along" is the combination of tau2 and tau1 whose gradient is orthogonal to
// tau1's (the chord's normal).
float beyond_hull_px(float t1, float t2, vec2 g1, vec2 g2) {
  float k = -dot(g1, g2) / max(dot(g1, g1), 1e-30);
  float along = t2 + k * t1;
  float beyond = max(min(0.0, k) - along, along - max(1.0, k));
  return beyond / max(length(g2 + k * g1), 1e-30);
}

// Beyond this many pixels from the edge it shares with a curved triangle, an
// interior triangle's pixels cannot reach the curve (the curve lies beyond
// that edge, and a pixel's box reaches sqrt(2)/2 px), so the conic, whose
// other branches may pass anywhere, is not consulted there.
const float kNearCurvePx = 0.75;
// A pixel's box reaches at most sqrt(2)/2 px from its centre (rounded up):
// tolerance::kFringeWidthPx, defined by the renderer when compiling.
const float kPixelReachPx = CURVETEXT_PIXEL_REACH_PX;
const float kThirdCurveMinChordPx = CURVETEXT_THIRD_CURVE_MIN_CHORD_PX;

// Folds in, for an interior triangle (kinds 3, 4), a curve across one of its
// edges or touching it at a vertex. `code` is the hull edge the triangle lies
// beyond: 0 the chord of a convex curve, 1 / 2 a leg of a concave one.
void fold_near_curve(inout float cov, inout vec2 nacc, float t1, float t2, float w, float code) {
  vec2 g1 = vec2(dFdx(t1), dFdy(t1));
  vec2 g2 = vec2(dFdx(t2), dFdy(t2));
  float e = code < 0.5 ? t1 : (code < 1.5 ? t2 : 1.0 - t1 - t2);
  vec2 ge = code < 0.5 ? g1 : (code < 1.5 ? g2 : -g1 - g2);
  float ge_len = length(ge);
  if (ge_len < 1e-20 || abs(e) > kNearCurvePx * ge_len) return;
  // The same past the ends of the hull: a triangle touching the curve at a
  // vertex can run far along the chord's line (a stem's edge continuing a
  // curve), where the conic's extension bends back across the edge.
  if (beyond_hull_px(t1, t2, g1, g2) > kNearCurvePx) return;
  float s = code < 0.5 ? 1.0 : -1.0;
  vec2 n;
  float a = conic_coverage(t1, t2, g1, g2, w, s, false, code, n);
  fold(cov, nacc, a, n);
}

void main() {
  if (u_debug == 2) {
    gl_FragColor = vec4(0.05, 0.35, 0.95, 1.0);
    return;
  }
  float kind = floor(v_info.x + 0.5);
  float coverage = 1.0;
  vec2 nacc = vec2(0.0);
  if (kind > 0.5 && kind < 1.5) {
    // Straight edges are antialiased only in full mode (the paper's single
    // pass leaves them aliased).
    if (u_aa == 2) {
      fold_line(coverage, nacc, v_coef.x);
      fold_line(coverage, nacc, v_coef.y);
      fold_line(coverage, nacc, v_coef.z);
      fold_line(coverage, nacc, v_coef.w);
    }
  } else if (kind > 1.5 && kind < 2.5) {
    float t1 = v_coef.x;
    float t2 = v_coef.y;
    float s = v_coef.z;
    float w = v_info.y;
    // tau is affine, so its screen derivatives are exact.
    vec2 g1 = vec2(dFdx(t1), dFdy(t1));
    vec2 g2 = vec2(dFdx(t2), dFdy(t2));
    float d;
    vec2 n;
    if (u_curve_mode == 0) {
      // Beyond the chord (tau1 < 0, only reached by fringes) tau1^2 would
      // resurrect the mirror image of the curve; for concave curves that
      // region is outside, which tau1*|tau1| keeps (same value and gradient
      // at tau1 = 0).
      d = conic_distance(t1, t2, g1, g2, w, s, s < 0.0, u_aa == 2, n);
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
      n = (glen > 1e-20) ? -s * gf / glen : vec2(1.0, 0.0);
      // Signed distance in pixels, positive on the filled side.
      d = (glen > 1e-20) ? -s * f / glen : -s * f * 1e20;
    }
    if (u_aa == 0) {
      coverage = d >= 0.0 ? 1.0 : 0.0;
    } else if (u_aa == 1) {
      coverage = clamp(0.5 + d, 0.0, 1.0);
    } else if (beyond_hull_px(t1, t2, g1, g2) > kPixelReachPx) {
      // A fringe's miter spike at an acute join reaches pixels whose box
      // misses the arc (and, near a convex join, the whole outline), where
      // the conic's extension may still read "inside" (a dark pixel past
      // the end of a stroke).
      coverage = 0.0;
    } else {
      float a = u_curve_mode == 0 ? conic_coverage(t1, t2, g1, g2, w, s, s < 0.0, v_coef.w > 0.5 ? 3.0 : -1.0, n) : boxcov(d, n);
      fold(coverage, nacc, a, n);
    }
  } else if (u_aa == 2) {
    // Interior triangles next to one (kind 3), two (kind 4) or three (kind
    // 5) curved triangles; solid unless antialiasing is full, as in the paper.
    float codes = floor(v_info.w + 0.5);
    float code_c = floor(codes / 9.0 + 0.01);
    codes -= 9.0 * code_c;
    float code_b = floor(codes / 3.0 + 0.01);
    float code_a = codes - 3.0 * code_b;
    fold_line(coverage, nacc, v_coef.x);
    fold_line(coverage, nacc, v_coef.y);
    fold_near_curve(coverage, nacc, v_tau.x, v_tau.y, v_info.y, code_a);
    if (kind < 3.5) {
      fold_line(coverage, nacc, v_coef.z);
      fold_line(coverage, nacc, v_coef.w);
    } else {
      fold_near_curve(coverage, nacc, v_coef.z, v_coef.w, v_info.z, code_b);
    }
    if (kind > 4.5) {
      // The third curve only where its chord spans a few pixels (see
      // tolerance::kThirdCurveMinChordPx): the position along the chord
      // (as in beyond_hull_px) changes by 1 over the chord's length.
      vec2 g1 = vec2(dFdx(v_fade.x), dFdy(v_fade.x));
      vec2 g2 = vec2(dFdx(v_fade.y), dFdy(v_fade.y));
      float k = -dot(g1, g2) / max(dot(g1, g1), 1e-30);
      float chord_px = 1.0 / max(length(g2 + k * g1), 1e-30);
      if (chord_px >= kThirdCurveMinChordPx) fold_near_curve(coverage, nacc, v_fade.x, v_fade.y, v_tau.z, code_c);
    }
  }
  // Every kind but 5: the far side of a feature thinner than a pixel, a
  // corner's other line, or a reflex corner's two sides (see a_fade in
  // vertex_format.hpp); full AA only.
  if (u_aa == 2 && kind < 4.5) {
    if (v_info.x - kind > 0.125) {  // kUnionFadeFlag
      fold_union(coverage, nacc, v_fade.x, v_fade.y);
    } else {
      fold_line(coverage, nacc, v_fade.x);
      fold_line(coverage, nacc, v_fade.y);
    }
  }
  if (coverage <= 0.0) {
    // Debug (paper Figure 1): what a curved triangle throws away.
    if (u_debug == 1 && kind > 1.5 && kind < 2.5) {
      gl_FragColor = vec4(1.0, 0.45, 0.0, 1.0);
      return;
    }
    discard;
  }
  gl_FragColor = u_color * (u_coverage_exponent == 1.0 ? coverage : pow(coverage, u_coverage_exponent));
}
