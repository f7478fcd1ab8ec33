// Full antialiasing, fragment stage: the exact area of this fragment's pixel
// box inside one triangle of the mesh (and, for a curved triangle, on the
// filled side of its arc). Drawn with additive blending into a coverage
// buffer (lib/gpu/renderer.cpp): the mesh's triangles tile the filled region
// exactly, so the sum over the triangles touching a pixel is its coverage,
// with no need for any triangle to know about its neighbours. Vertex stage:
// curve.vert.glsl, which grows every triangle by a pixel's reach
// (lib/gpu/pack.cpp); layout: lib/gpu/vertex_format.hpp.
#extension GL_OES_standard_derivatives : enable
precision highp float;

uniform vec4 u_color;  // premultiplied; white for the coverage buffer
uniform float u_coverage_exponent;  // 1 / gamma; 1 for the coverage buffer
uniform int u_curve_mode;  // 0 exact, 1 the paper's equation 2

varying vec4 v_coef;  // (tau1, tau2, s, 0): the triangle's barycentrics; s a curve's filled side
varying vec4 v_info;  // (kind, w, ...): kind 0 interior, 2 curved; w the conic's weight

// A pixel's box reaches at most sqrt(2)/2 px from its centre (rounded up):
// tolerance::kFringeWidthPx, defined by the renderer when compiling.
const float kPixelReachPx = CURVETEXT_PIXEL_REACH_PX;

// Clips the segment p + t u, t in [t0, t1], to the half-plane h (inside where
// dot(h.xy, x) + h.z >= 0); the segment's own half-plane has the normal
// (u.y, -u.x). Lines within 1e-4 of each other in angle (radians) and offset
// (pixels) count as one. Facing the same way, exactly one of the pair may be
// an edge, or rounding would count the area next to it twice (or not at
// all); `yield_on_tie` says whether the segment gives way. Facing opposite
// ways (a curve's tangent on its control triangle's leg), both stay: the
// polygon between them is flat, and their two edges cancel. This moves an
// edge by at most ~1e-4 px. Beyond that, t = -c / k is off by at most
// ~1e-7 / 1e-4 = 1e-3 of a pixel.
const float kParallel = 1e-4;
void clip_segment(vec3 h, vec2 p, vec2 u, bool yield_on_tie, inout float t0, inout float t1) {
  float c = dot(h.xy, p) + h.z;
  float k = dot(h.xy, u);
  if (abs(k) < kParallel) {
    bool tie = abs(c) < kParallel;
    bool same_way = dot(h.xy, vec2(u.y, -u.x)) > 0.0;
    if (tie ? (yield_on_tie && same_way) : c < 0.0) t1 = t0 - 1.0;
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
const int kMaxPlanes = 6;
float convex_area(vec3 L[6], int n) {
  float area = 0.0;
  for (int s = 0; s < 4; ++s) {
    vec2 nn = s == 0 ? vec2(1.0, 0.0) : s == 1 ? vec2(-1.0, 0.0) : s == 2 ? vec2(0.0, 1.0) : vec2(0.0, -1.0);
    vec2 p = -0.5 * nn;
    vec2 u = vec2(-nn.y, nn.x);
    float t0 = -0.5;
    float t1 = 0.5;
    for (int j = 0; j < kMaxPlanes; ++j) {
      if (j >= n) break;
      clip_segment(L[j], p, u, true, t0, t1);
    }
    area += 0.25 * max(t1 - t0, 0.0);
  }
  for (int i = 0; i < kMaxPlanes; ++i) {
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
    for (int j = 0; j < kMaxPlanes; ++j) {
      if (j >= n) break;
      if (j != i) clip_segment(L[j], p, u, j < i, t0, t1);
    }
    area += 0.5 * h.z * max(t1 - t0, 0.0);
  }
  return area;
}

// The half-plane of an affine function e with screen gradient g (pixels):
// unit normal towards e > 0 and the signed distance of the pixel centre.
vec3 half_plane(float e, vec2 g) {
  float len = max(length(g), 1e-30);
  return vec3(g / len, e / len);
}

// The arc's point at parameter t and its derivative (pixels per unit of t),
// for the control triangle p0, c, p2 (pixels from the centre) and weight w.
// Exact: the rational quadratic with weights 1, w, 1, X / W with X, W the
// homogeneous numerator and denominator. Paper (u_curve_mode 1): the curve
// of the paper's equation 2, v = w u (1 - u) / den(u) in its (u, v) =
// (tau1 / 2 + tau2, tau1 / 2), with t = u; the same for w = 1 only.
void arc_at(vec2 p0, vec2 c, vec2 p2, float w, float t, out vec2 b, out vec2 db) {
  if (u_curve_mode == 1) {
    float den = (2.0 - 2.0 * w) * t * t + 2.0 * (w - 1.0) * t + 1.0;
    den = abs(den) < 1e-12 ? 1e-12 : den;
    float dden = 2.0 * (2.0 - 2.0 * w) * t + 2.0 * (w - 1.0);
    float v = w * t * (1.0 - t) / den;
    float dv = w * ((1.0 - 2.0 * t) * den - t * (1.0 - t) * dden) / (den * den);
    // Position = p0 + tau1 (c - p0) + tau2 (p2 - p0), tau1 = 2v, tau2 = u - v.
    b = p0 + 2.0 * v * (c - p0) + (t - v) * (p2 - p0);
    db = 2.0 * dv * (c - p0) + (1.0 - dv) * (p2 - p0);
    return;
  }
  float a = 1.0 - t;
  vec2 x = a * a * p0 + 2.0 * w * t * a * c + t * t * p2;
  float wt = a * a + 2.0 * w * t * a + t * t;
  vec2 dx = 2.0 * (a * (w * c - p0) + t * (p2 - w * c));
  float dw = 2.0 * (a * (w - 1.0) + t * (1.0 - w));
  b = x / wt;
  db = (dx * wt - x * dw) / (wt * wt);
}

// The tangent through arc point b with derivative d, as the half-plane on
// the chord's side (through the chord's midpoint m; chord = p2 - p0).
vec3 tangent_through(vec2 b, vec2 d, vec2 chord, vec2 m) {
  if (dot(d, d) < 1e-20) d = chord;
  vec2 n = normalize(vec2(-d.y, d.x));
  if (dot(n, m - b) < 0.0) n = -n;
  return vec3(n, -dot(n, b));
}

// The arc's tangent at t, as above.
vec3 tangent_plane(vec2 p0, vec2 c, vec2 p2, float w, float t, vec2 m) {
  vec2 b;
  vec2 d;
  arc_at(p0, c, p2, w, t, b, d);
  return tangent_through(b, d, p2 - p0, m);
}

void main() {
  float t1 = v_coef.x;
  float t2 = v_coef.y;
  float t0 = 1.0 - t1 - t2;
  // tau is affine, so its screen derivatives are exact.
  vec2 g1 = vec2(dFdx(t1), dFdy(t1));
  vec2 g2 = vec2(dFdx(t2), dFdy(t2));
  vec2 g0 = -g1 - g2;
  vec3 L[6];
  L[0] = half_plane(t0, g0);
  L[1] = half_plane(t1, g1);
  L[2] = half_plane(t2, g2);
  // The box misses the triangle when it lies wholly outside one of its edges.
  for (int i = 0; i < 3; ++i) {
    if (L[i].z <= -0.5 * (abs(L[i].x) + abs(L[i].y))) discard;
  }
  float area;
  // The triangle's smallest altitude in pixels is 1 / its largest barycentric
  // gradient. Thinner than CURVETEXT_THIN_TRIANGLE_PX, it counts as empty: it
  // lies within that distance of a line, so it holds at most sqrt(2) times
  // that of any pixel, while the clipping and the inversion below lose their
  // digits on it (tolerances.hpp, kThinTrianglePx).
  float steepest = max(max(dot(g0, g0), dot(g1, g1)), dot(g2, g2));
  if (steepest * CURVETEXT_THIN_TRIANGLE_PX * CURVETEXT_THIN_TRIANGLE_PX > 1.0) discard;
  if (v_info.x < 1.5) {
    area = convex_area(L, 3);
  } else {
    // A curved triangle: the part of the box inside its control triangle on
    // the filled side of the arc. Between the chord and the arc lies a convex
    // region, the intersection of the arc's tangent half-planes; three
    // tangents spread over the pixel bound it to within the slivers between
    // them (a circle of radius R with tangents 0.75 px apart: 0.018 / R of a
    // pixel per gap): at the arc's point nearest the pixel centre and 0.75 px
    // of arc to either side, but at most a quarter of the arc's parameter
    // range (an arc a few pixels long turns a lot over 0.75 px: with its legs,
    // the tangents at t = 0 and 1, the tangents then split it in quarters;
    // spread by arc length alone they left up to 0.2 of a pixel out at 32 px).
    // s = +1: filled on the chord's side; -1: beyond the arc, the control
    // triangle minus that region.
    // The control points in pixels from the centre: solving g1 . x = dtau1,
    // g2 . x = dtau2, whose inverse has the columns e1 and e2 (a unit step
    // of tau1 or tau2).
    float det = g1.x * g2.y - g1.y * g2.x;
    // A long, flat control triangle (k = longest edge / smallest altitude =
    // steepest / |det|, steepest the largest squared gradient) loses digits
    // here and in the tangent clipping below: an 11.6 x 0.006 px piece of a
    // Noto Sans CJK glyph at 32 px/em (k about 2,000) put 0.17 of coverage
    // into an empty pixel, and still did with its control points passed
    // exactly (tried: as window-linear varyings). Where 1e-7 k^2 px, which
    // fits that case, exceeds the altitude, the region (within the altitude
    // of a line) counts as empty: the smaller error.
    if (1e-7 * steepest * steepest * sqrt(steepest) > det * det) {
      area = 0.0;
    } else {
      vec2 e1 = vec2(g2.y, -g2.x) / det;
      vec2 e2 = vec2(-g1.y, g1.x) / det;
      vec2 p0 = -t1 * e1 - t2 * e2;
      vec2 c = p0 + e1;
      vec2 p2 = p0 + e2;
      vec2 m = 0.5 * (p0 + p2);
      float s = v_coef.z;
      float w = v_info.y;
      // The arc's point nearest the pixel centre: Gauss-Newton on
      // dot(B(t), B'(t)) = 0 from the centre's projection on the chord.
      vec2 chord = p2 - p0;
      float t = clamp(-dot(p0, chord) / max(dot(chord, chord), 1e-30), 0.0, 1.0);
      vec2 b;
      vec2 db;
      for (int i = 0; i < 3; ++i) {
        arc_at(p0, c, p2, w, t, b, db);
        t = clamp(t - dot(b, db) / max(dot(db, db), 1e-30), 0.0, 1.0);
      }
      arc_at(p0, c, p2, w, t, b, db);
      float dt = min(0.75 / max(length(db), 1e-6), 0.25);
      L[3] = tangent_through(b, db, chord, m);
      L[4] = tangent_plane(p0, c, p2, w, max(t - dt, 0.0), m);
      L[5] = tangent_plane(p0, c, p2, w, min(t + dt, 1.0), m);
      float inside = convex_area(L, 6);
      area = s > 0.0 ? inside : convex_area(L, 3) - inside;
    }
  }
  area = clamp(area, 0.0, 1.0);
  if (area <= 0.0) discard;
  gl_FragColor = u_color * (u_coverage_exponent == 1.0 ? area : pow(area, u_coverage_exponent));
}
