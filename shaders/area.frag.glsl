// Full antialiasing, fragment stage: the exact area of this fragment's pixel
// box inside one triangle of the mesh (and, for a curved triangle, on the
// filled side of its arc). Compiled twice, for interior triangles
// (CURVETEXT_AREA_CURVED 0) and for curved ones (1), drawn in two passes:
// each program holds only its own work. Drawn with additive blending into a coverage
// buffer (lib/gpu/renderer.cpp): the mesh's triangles tile the filled region
// exactly, so the sum over the triangles touching a pixel is its coverage,
// with no need for any triangle to know about its neighbours. Vertex stage:
// curve.vert.glsl, which grows every triangle by a pixel's reach
// (lib/gpu/pack.cpp); layout: lib/gpu/vertex_format.hpp.
#extension GL_OES_standard_derivatives : enable
precision highp float;

uniform vec4 u_color;  // premultiplied; white for the coverage buffer
uniform float u_coverage_exponent;  // 1 / gamma, in the program compiled with CURVETEXT_GAMMA 1
uniform int u_curve_mode;  // 0 exact, 1 the paper's equation 2

varying vec4 v_coef;  // (tau1, tau2, s, 0): the triangle's barycentrics; s a curve's filled side
varying vec4 v_info;  // (kind, w, ...): kind 0 interior, 2 curved; w the conic's weight


// The mean of clamp(u, 0, 1) over u in [a, b] (or its value where a = b),
// exactly: the integral over the part in [0, 1] and the part beyond 1,
// written with differences of the clamped ends so that a short interval
// keeps its digits.
float mean_clamp(float a, float b) {
  float lo = min(a, b);
  float hi = max(a, b);
  float cl = clamp(lo, 0.0, 1.0);
  float ch = clamp(hi, 0.0, 1.0);
  float integral = 0.5 * (ch + cl) * (ch - cl) + max(hi - max(lo, 1.0), 0.0);
  float len = hi - lo;
  return len > 0.0 ? clamp(integral / len, 0.0, 1.0) : cl;
}

// One edge p -> q of a polygon (pixels from the pixel's centre) in the exact
// area of the polygon inside the pixel's box [-0.5, 0.5]^2, by Green's
// theorem: the area is the sum over the polygon's edges of the integral, over
// the part of the edge within the box's rows, of the width of the box's row
// left of the edge, clamp(x + 0.5, 0, 1). Signed by the polygon's
// orientation; horizontal edges add nothing. No loops and no branches: a
// software rasteriser runs every path of a shader, so the cost is the code.
float edge_area(vec2 p, vec2 q) {
  float y0 = clamp(p.y, -0.5, 0.5);
  float y1 = clamp(q.y, -0.5, 0.5);
  float dy = q.y - p.y;
  float inv = dy != 0.0 ? 1.0 / dy : 0.0;
  float x0 = p.x + (q.x - p.x) * clamp((y0 - p.y) * inv, 0.0, 1.0);
  float x1 = p.x + (q.x - p.x) * clamp((y1 - p.y) * inv, 0.0, 1.0);
  return (y1 - y0) * mean_clamp(x0 + 0.5, x1 + 0.5);
}

float triangle_area(vec2 a, vec2 b, vec2 c) {
  return edge_area(a, b) + edge_area(b, c) + edge_area(c, a);
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

// Where the tangents P + s D and Q + r E meet; where they are parallel (two
// tangents at one point, or a straight stretch), halfway between P and Q.
vec2 tangents_meet(vec2 p, vec2 d, vec2 q, vec2 e) {
  float den = d.x * e.y - d.y * e.x;
  vec2 pq = q - p;
  bool parallel = abs(den) <= 1e-6 * length(d) * length(e);
  float s = (pq.x * e.y - pq.y * e.x) / (parallel ? 1.0 : den);
  return parallel ? 0.5 * (p + q) : p + s * d;
}

// The vertex where lines a and b (as from half_plane) meet.
vec2 lines_meet(vec3 a, vec3 b) {
  float d = a.x * b.y - a.y * b.x;
  d = abs(d) < 1e-20 ? 1e-20 : d;
  return vec2(a.y * b.z - b.y * a.z, b.x * a.z - a.x * b.z) / d;
}

void main() {
  float t1 = v_coef.x;
  float t2 = v_coef.y;
  float t0 = 1.0 - t1 - t2;
  // tau is affine, so its screen derivatives are exact.
  vec2 g1 = vec2(dFdx(t1), dFdy(t1));
  vec2 g2 = vec2(dFdx(t2), dFdy(t2));
  vec2 g0 = -g1 - g2;
  vec3 L0 = half_plane(t0, g0);
  vec3 L1 = half_plane(t1, g1);
  vec3 L2 = half_plane(t2, g2);
  // The box misses the triangle when it lies wholly outside one of its edges.
  if (L0.z <= -0.5 * (abs(L0.x) + abs(L0.y)) || L1.z <= -0.5 * (abs(L1.x) + abs(L1.y)) ||
      L2.z <= -0.5 * (abs(L2.x) + abs(L2.y)))
    discard;
  // The triangle's smallest altitude in pixels is 1 / its largest barycentric
  // gradient. Thinner than CURVETEXT_THIN_TRIANGLE_PX, it counts as empty: it
  // lies within that distance of a line, so it holds at most sqrt(2) times
  // that of any pixel, while the area below loses its digits on it
  // (tolerances.hpp, kThinTrianglePx).
  float steepest = max(max(dot(g0, g0), dot(g1, g1)), dot(g2, g2));
  if (steepest * CURVETEXT_THIN_TRIANGLE_PX * CURVETEXT_THIN_TRIANGLE_PX > 1.0) discard;
  float area;
#if CURVETEXT_AREA_CURVED == 0
  // An interior triangle: its corners (tau_k = 1 where the other two edges
  // meet), from the normalised edge lines, so each edge stays as exact as
  // its line however thin the triangle.
  area = abs(triangle_area(lines_meet(L1, L2), lines_meet(L0, L2), lines_meet(L0, L1)));
#else
  // A curved triangle: the part of the box inside its control triangle on
  // the filled side of its arc. Between the chord and the arc lies a convex
  // region, bounded (from outside) by the polygon of the arc's tangents: the
  // legs (the tangents at its ends) and three tangents spread over the pixel,
  // which bound it to within the slivers between them (a circle of radius R
  // with tangents 0.75 px apart: 0.018 / R of a pixel per gap): at the arc's
  // point nearest the pixel centre and 0.75 px of arc to either side, but at
  // most a quarter of the arc's parameter range (an arc a few pixels long
  // turns a lot over 0.75 px: with its legs the tangents then split it in
  // quarters). s = +1: filled on the chord's side; -1: beyond the arc, the
  // control triangle minus that region.
  // The control points in pixels from the centre: solving g1 . x = dtau1,
  // g2 . x = dtau2, whose inverse has the columns e1 and e2 (a unit step of
  // tau1 or tau2).
  float det = g1.x * g2.y - g1.y * g2.x;
  // A long, flat control triangle (k = longest edge / smallest altitude =
  // steepest / |det|, steepest the largest squared gradient) loses digits
  // here: an 11.6 x 0.006 px piece of a Noto Sans CJK glyph at 32 px/em (k
  // about 2,000) put 0.17 of coverage into an empty pixel. Where 1e-7 k^2 px,
  // which fits that case, exceeds the altitude, the region (within the
  // altitude of a line) counts as empty: the smaller error.
  if (1e-7 * steepest * steepest * sqrt(steepest) > det * det) discard;
  vec2 e1 = vec2(g2.y, -g2.x) / det;
  vec2 e2 = vec2(-g1.y, g1.x) / det;
  vec2 p0 = -t1 * e1 - t2 * e2;
  vec2 c = p0 + e1;
  vec2 p2 = p0 + e2;
  float w = v_info.y;
  // The arc's point nearest the pixel centre: Gauss-Newton on
  // dot(B(t), B'(t)) = 0, from the nearer of two starts: the centre's
  // projection on the chord, and the arc's point on the ray from the control
  // point through the centre (along the ray tau0 : tau2 stays as at the
  // centre; on the arc it is (1 - t)^2 : t^2). A heavy arc (large w) crowds
  // its parameter at the apex: from the chord alone the iteration stays far
  // from a pixel on its flanks, from the ray alone from one at its apex.
  vec2 chord = p2 - p0;
  float t_chord = clamp(-dot(p0, chord) / max(dot(chord, chord), 1e-30), 0.0, 1.0);
  float r0 = sqrt(max(t0, 0.0));
  float r2 = sqrt(max(t2, 0.0));
  float t_ray = r0 + r2 > 0.0 ? r2 / (r0 + r2) : t_chord;
  vec2 b;
  vec2 db;
  vec2 b_ray;
  arc_at(p0, c, p2, w, t_chord, b, db);
  arc_at(p0, c, p2, w, t_ray, b_ray, db);
  float t = dot(b_ray, b_ray) < dot(b, b) ? t_ray : t_chord;
  for (int i = 0; i < 3; ++i) {
    arc_at(p0, c, p2, w, t, b, db);
    t = clamp(t - dot(b, db) / max(dot(db, db), 1e-30), 0.0, 1.0);
  }
  arc_at(p0, c, p2, w, t, b, db);
  float dt = min(0.75 / max(length(db), 1e-6), 0.25);
  vec2 ba;
  vec2 da;
  vec2 bc;
  vec2 dc;
  arc_at(p0, c, p2, w, max(t - dt, 0.0), ba, da);
  arc_at(p0, c, p2, w, min(t + dt, 1.0), bc, dc);
  vec2 q1 = tangents_meet(p0, c - p0, ba, da);
  vec2 q2 = tangents_meet(ba, da, b, db);
  vec2 q3 = tangents_meet(b, db, bc, dc);
  vec2 q4 = tangents_meet(bc, dc, p2, p2 - c);
  float orient = det > 0.0 ? 1.0 : -1.0;  // the sign of the triangle (p0, c, p2) in these axes
  float region = orient * (edge_area(p0, q1) + edge_area(q1, q2) + edge_area(q2, q3) + edge_area(q3, q4) +
                           edge_area(q4, p2) + edge_area(p2, p0));
  area = v_coef.z > 0.0 ? region : orient * triangle_area(p0, c, p2) - region;
#endif
  area = clamp(area, 0.0, 1.0);
  if (area <= 0.0) discard;
#if CURVETEXT_GAMMA
  area = pow(area, u_coverage_exponent);
#endif
  gl_FragColor = u_color * area;
}
