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

// The inverse of boxcov: the signed distance (pixels) at which a straight
// edge with unit normal n covers `cov` of the box. A curve's coverage (from
// its sub-boxes) becomes the half-plane that covers the same area, so it can
// be combined with other boundaries exactly as a line.
float box_distance(float cov, vec2 n) {
  float a = abs(n.x);
  float b = abs(n.y);
  float hi = 0.5 * (a + b);
  if (cov >= 1.0) return hi;
  if (cov <= 0.0) return -hi;
  float lo = max(a, b);
  float sm = min(a, b);
  if (sm < 1e-3) return (cov - 0.5) * lo;
  float knee = sm / (2.0 * lo);  // the coverage where the ramp turns linear
  if (cov < knee) return sqrt(2.0 * a * b * cov) - hi;
  if (cov > 1.0 - knee) return hi - sqrt(2.0 * a * b * (1.0 - cov));
  return (cov - 0.5) * lo;
}

// The boundaries that cut this fragment's pixel box, as half-planes
// (n.x, n.y, d): inside where dot(n, x) + d >= 0, x the offset from the pixel
// centre in pixels, n a unit normal. Full AA takes the coverage as the exact
// area of the box inside all of them (the shape near a pixel is the
// intersection of the sides it knows: a convex corner, both sides of a
// feature thinner than a pixel), and subtracts the parts in the outside wedge
// of each reflex corner (where the shape is the union of two sides).
const int kMaxPlanes = 8;
vec3 g_planes[8];
int g_plane_count = 0;
bool g_empty = false;    // a boundary has the whole box outside
vec3 g_wedge[4];         // up to two reflex corners' outside half-planes
int g_wedge_count = 0;

// Adds the half-plane dot(n, x) + d >= 0 (n a unit normal towards the filled
// side, d the signed distance of the pixel centre in pixels), unless it does
// not cut the box.
void add_half_plane(vec2 n, float d) {
  float hi = 0.5 * (abs(n.x) + abs(n.y));  // the box's reach along n
  if (d >= hi) return;
  if (d <= -hi) {
    g_empty = true;
    return;
  }
  for (int i = kMaxPlanes - 1; i > 0; --i) g_planes[i] = g_planes[i - 1];
  g_planes[0] = vec3(n, d);
  g_plane_count = g_plane_count + 1;
}

// Adds a boundary whose side covers `cov` of the box (a curve's estimate),
// with unit normal n towards the filled side.
void add_boundary(float cov, vec2 n) { add_half_plane(n, box_distance(cov, n)); }

// Clips the segment p + t u, t in [t0, t1], to the half-plane h. Lines
// within 1e-4 of each other in angle (radians) and offset (pixels) count as
// one: of such a pair exactly one may be an edge, or rounding would count the
// area next to it twice (or not at all); `yield_on_tie` says whether the
// segment gives way. Treating them so moves an edge by at most ~1e-4 px.
// Beyond that, t = -c / k is off by at most ~1e-7 / 1e-4 = 1e-3 of a pixel.
const float kParallel = 1e-4;
void clip_segment(vec3 h, vec2 p, vec2 u, bool yield_on_tie, inout float t0, inout float t1) {
  float c = dot(h.xy, p) + h.z;
  float k = dot(h.xy, u);
  if (abs(k) < kParallel) {
    bool tie = abs(c) < kParallel;
    if (tie ? yield_on_tie : c < 0.0) t1 = t0 - 1.0;
  } else if (k > 0.0) {
    t0 = max(t0, -c / k);
  } else {
    t1 = min(t1, -c / k);
  }
}

// Exact area of the unit box (centred on the origin) inside the half-planes
// L[0 .. n): for a convex polygon, the sum over its edges of the signed
// height from the origin times the edge's length, halved. Each line's edge is
// its chord through the box clipped by the other lines; the box's sides are
// clipped likewise. Loops over constants only (GLSL ES 1.00).
float convex_area(vec3 L[12], int n) {
  float area = 0.0;
  for (int s = 0; s < 4; ++s) {
    vec2 nn = s == 0 ? vec2(1.0, 0.0) : s == 1 ? vec2(-1.0, 0.0) : s == 2 ? vec2(0.0, 1.0) : vec2(0.0, -1.0);
    vec2 p = -0.5 * nn;
    vec2 u = vec2(-nn.y, nn.x);
    float t0 = -0.5;
    float t1 = 0.5;
    for (int j = 0; j < 12; ++j) {
      if (j >= n) break;
      clip_segment(L[j], p, u, true, t0, t1);
    }
    area += 0.25 * max(t1 - t0, 0.0);
  }
  for (int i = 0; i < 12; ++i) {
    if (i >= n) break;
    vec3 h = L[i];
    vec2 p = -h.z * h.xy;
    vec2 u = vec2(-h.y, h.x);
    float t0 = -2.0;
    float t1 = 2.0;
    clip_segment(vec3(1.0, 0.0, 0.5), p, u, false, t0, t1);
    clip_segment(vec3(-1.0, 0.0, 0.5), p, u, false, t0, t1);
    clip_segment(vec3(0.0, 1.0, 0.5), p, u, false, t0, t1);
    clip_segment(vec3(0.0, -1.0, 0.5), p, u, false, t0, t1);
    for (int j = 0; j < 12; ++j) {
      if (j >= n) break;
      if (j != i) clip_segment(L[j], p, u, j < i, t0, t1);
    }
    area += 0.5 * h.z * max(t1 - t0, 0.0);
  }
  return clamp(area, 0.0, 1.0);
}

// The area inside the planes and, with `w0` / `w1`, inside the outside wedge
// of reflex corner 0 / 1.
float planes_area(bool w0, bool w1) {
  vec3 L[12];
  int n = 0;
  for (int i = 0; i < kMaxPlanes; ++i) {
    if (i >= g_plane_count) break;
    L[i] = g_planes[i];
    n = i + 1;
  }
  for (int k = 0; k < 4; ++k) {
    bool take = k < 2 ? w0 : w1;
    if (!take) continue;
    for (int i = 11; i > 0; --i) L[i] = L[i - 1];
    L[0] = g_wedge[k];
    n = n + 1;
  }
  return convex_area(L, n);
}

float combined_coverage() {
  if (g_empty) return 0.0;
  float a = g_plane_count == 0 ? 1.0
            : g_plane_count == 1 ? boxcov(g_planes[0].z, g_planes[0].xy)
                                 : planes_area(false, false);
  bool w0 = g_wedge_count > 0;
  bool w1 = g_wedge_count > 1;
  if (w0) a -= planes_area(true, false);
  if (w1) a -= planes_area(false, true);
  if (w0 && w1) a += planes_area(true, true);
  return clamp(a, 0.0, 1.0);
}

// Adds the boundary of one distance slot (outline units, affine, positive
// inside).
void add_line(float c) {
  vec2 g = vec2(dFdx(c), dFdy(c));
  float len = length(g);
  // A constant slot (unused, 1e6) has no gradient: no edge here.
  if (len < 1e-12) return;
  add_half_plane(g / len, c / len);
}

// Adds the two sides of a reflex corner (a_fade or a_coef's last pair of an
// interior triangle flagged kUnionFadeFlag / kUnionCoefFlag, see
// vertex_format.hpp): the shape there is the union of both half-planes, so
// the box loses the part in the intersection of the two outsides, a wedge.
void add_union(float c0, float c1) {
  vec2 g0 = vec2(dFdx(c0), dFdy(c0));
  vec2 g1 = vec2(dFdx(c1), dFdy(c1));
  float l0 = length(g0);
  float l1 = length(g1);
  if (l0 < 1e-12 || l1 < 1e-12) return;
  vec2 n0 = g0 / l0;
  vec2 n1 = g1 / l1;
  float d0 = c0 / l0;
  float d1 = c1 / l1;
  float h0 = 0.5 * (abs(n0.x) + abs(n0.y));
  float h1 = 0.5 * (abs(n1.x) + abs(n1.y));
  // The box inside either side: the union covers it.
  if (d0 >= h0 || d1 >= h1) return;
  if (d0 <= -h0 && d1 <= -h1) {
    g_empty = true;
    return;
  }
  if (g_wedge_count >= 2) return;
  // A side the box lies wholly outside of bounds nothing: the wedge is the
  // other outside half-plane alone (its line repeated).
  vec3 o0 = d0 <= -h0 ? vec3(-n1, -d1) : vec3(-n0, -d0);
  vec3 o1 = d1 <= -h1 ? vec3(-n0, -d0) : vec3(-n1, -d1);
  if (g_wedge_count == 0) {
    g_wedge[0] = o0;
    g_wedge[1] = o1;
  } else {
    g_wedge[2] = o0;
    g_wedge[3] = o1;
  }
  g_wedge_count = g_wedge_count + 1;
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
// add_near_curve) beyond which the shape is solid (an interior triangle
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
  // the combination would take this curve and a neighbour continuing it smoothly for
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

// Adds, for an interior triangle (kinds 3, 4), a curve across one of its
// edges or touching it at a vertex. `code` is the hull edge the triangle lies
// beyond: 0 the chord of a convex curve, 1 / 2 a leg of a concave one.
void add_near_curve(float t1, float t2, float w, float code) {
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
  add_boundary(a, n);
}

void main() {
  if (u_debug == 2) {
    gl_FragColor = vec4(0.05, 0.35, 0.95, 1.0);
    return;
  }
  float kind = floor(v_info.x + 0.5);
  // Flags added to the kind (vertex_format.hpp): kUnionFadeFlag 0.25,
  // kUnionCoefFlag 0.125.
  float flags = v_info.x - kind;
  bool fade_union = flags > 0.1875;
  bool coef_union = mod(flags, 0.25) > 0.0625;
  float coverage = 1.0;
  if (kind > 0.5 && kind < 1.5) {
    // Straight edges are antialiased only in full mode (the paper's single
    // pass leaves them aliased).
    if (u_aa == 2) {
      add_line(v_coef.x);
      add_line(v_coef.y);
      if (coef_union) {
        add_union(v_coef.z, v_coef.w);
      } else {
        add_line(v_coef.z);
        add_line(v_coef.w);
      }
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
      add_boundary(a, n);
    }
  } else if (u_aa == 2) {
    // Interior triangles next to one (kind 3), two (kind 4) or three (kind
    // 5) curved triangles; solid unless antialiasing is full, as in the paper.
    float codes = floor(v_info.w + 0.5);
    float code_c = floor(codes / 9.0 + 0.01);
    codes -= 9.0 * code_c;
    float code_b = floor(codes / 3.0 + 0.01);
    float code_a = codes - 3.0 * code_b;
    add_line(v_coef.x);
    add_line(v_coef.y);
    add_near_curve(v_tau.x, v_tau.y, v_info.y, code_a);
    if (kind < 3.5 && coef_union) {
      add_union(v_coef.z, v_coef.w);
    } else if (kind < 3.5) {
      add_line(v_coef.z);
      add_line(v_coef.w);
    } else {
      add_near_curve(v_coef.z, v_coef.w, v_info.z, code_b);
    }
    if (kind > 4.5) {
      // The third curve only where its chord spans a few pixels (see
      // tolerance::kThirdCurveMinChordPx): the position along the chord
      // (as in beyond_hull_px) changes by 1 over the chord's length.
      vec2 g1 = vec2(dFdx(v_fade.x), dFdy(v_fade.x));
      vec2 g2 = vec2(dFdx(v_fade.y), dFdy(v_fade.y));
      float k = -dot(g1, g2) / max(dot(g1, g1), 1e-30);
      float chord_px = 1.0 / max(length(g2 + k * g1), 1e-30);
      if (chord_px >= kThirdCurveMinChordPx) add_near_curve(v_fade.x, v_fade.y, v_tau.z, code_c);
    }
  }
  // Every kind but 5: the far side of a feature thinner than a pixel, a
  // corner's other line, or a reflex corner's two sides (see a_fade in
  // vertex_format.hpp); full AA only.
  if (u_aa == 2 && kind < 4.5) {
    if (fade_union) {
      add_union(v_fade.x, v_fade.y);
    } else {
      add_line(v_fade.x);
      add_line(v_fade.y);
    }
  }
  if (u_aa == 2) coverage = min(coverage, combined_coverage());
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
