// Curve shader, vertex stage (GLSL ES 1.00; a preamble added at compile time
// selects #version 100 or desktop 330 core). Vertex layout: lib/gpu/vertex_format.hpp.
precision highp float;

attribute vec4 a_pos;   // (x, y, ox, oy): outline units, fringe offset per unit of dilation
attribute vec4 a_coef;  // (c0, c1, c2, c3)
attribute vec4 a_info;  // (kind, w or dc2, dc0, dc1)
attribute vec4 a_fade;  // (f0, f1, df0, df1): two more boundary lines, any kind

uniform mat3 u_transform;     // outline units -> framebuffer pixels, y down (projective)
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform float u_fringe_px;    // fringe width in pixels (0 unless AA is full)

varying vec4 v_coef;
varying vec4 v_info;  // a_info: (kind, weight, ...) see vertex_format.hpp
varying vec3 v_tau;   // kinds 3-5: (tau1, tau2) of the neighbouring curve A; kind 5: w of curve C
varying vec2 v_fade;  // distances to the two a_fade lines

// Vertices shared between triangles must land on identical positions, or
// rasterisation leaves cracks / double-blended pixels along shared edges.
invariant gl_Position;

void main() {
  // Dilation in outline units; 0 makes the fringe triangles zero-area. The
  // smallest stretch of u_transform at this vertex (the smaller singular
  // value of its Jacobian) turns pixels into outline units, so the fringe is
  // at least u_fringe_px wide in every direction under rotation, non-uniform
  // scale, skew and perspective. Vertices at the same position with the same
  // offset get the same t, so shared fringe vertices stay bit-identical.
  vec3 h = u_transform * vec3(a_pos.xy, 1.0);
  vec2 hp = h.xy / h.z;
  mat2 jac = mat2(u_transform[0].xy - hp * u_transform[0].z, u_transform[1].xy - hp * u_transform[1].z) / h.z;
  float ss = dot(jac[0], jac[0]) + dot(jac[1], jac[1]);
  float det = abs(jac[0].x * jac[1].y - jac[1].x * jac[0].y);
  float hi = sqrt(0.5 * (ss + sqrt(max(ss * ss - 4.0 * det * det, 0.0))));
  float t = u_fringe_px > 0.0 ? u_fringe_px * hi / max(det, 1e-30) : 0.0;
  // Kinds 3-5 (interior triangles next to curves) never move; their
  // offset slot carries curve A's barycentrics instead, and kind 5's a_fade
  // curve C's (tau1, tau2, w) instead of two lines.
  bool next_to_curve = a_info.x > 2.5;
  bool three_curves = a_info.x > 4.5;
  vec2 p = next_to_curve ? a_pos.xy : a_pos.xy + a_pos.zw * t;
  v_tau = next_to_curve ? vec3(a_pos.zw, three_curves ? a_fade.z : 0.0) : vec3(0.0);
  // For edges (kind 1) the weight slot carries the derivative of c2.
  float dc2 = (a_info.x > 0.5 && a_info.x < 1.5) ? a_info.y : 0.0;
  vec4 dcoef = next_to_curve ? vec4(0.0) : vec4(a_info.z, a_info.w, dc2, 0.0);
  v_coef = a_coef + dcoef * t;
  v_info = a_info;
  v_fade = three_curves ? a_fade.xy : a_fade.xy + a_fade.zw * t;
  vec3 q = u_transform * vec3(p, 1.0);
  // Homogeneous clip coordinates: the GPU divides by q.z after clipping and
  // interpolates the varyings perspective-correctly (affine in outline units).
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, 0.0, q.z);
}
