// Curve shader, vertex stage (GLSL ES 1.00; a preamble added at compile time
// selects #version 100 or desktop 330 core), shared by the single-pass modes
// (curve.frag.glsl) and full antialiasing (area.frag.glsl). Vertex layout:
// lib/gpu/vertex_format.hpp.
precision highp float;

attribute vec4 a_pos;   // (x, y, ox, oy): outline units, growth per unit of dilation
attribute vec4 a_info;  // (corner + 3 side, w, dtau1, dtau2)

uniform mat3 u_transform;     // outline units -> framebuffer pixels, y down (projective)
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform float u_fringe_px;    // growth in pixels (0: the triangles as they are)

varying vec4 v_coef;  // (tau1, tau2, s, 0): barycentrics; s +1 convex curve, -1 concave, 0 interior
varying vec4 v_info;  // (kind, w, 0, 0): kind 0 interior, 2 curved; w the conic weight

void main() {
  // Dilation in outline units. The smallest stretch of u_transform at this
  // vertex (the smaller singular value of its Jacobian) turns pixels into
  // outline units, so every edge moves out by at least u_fringe_px pixels
  // under rotation, non-uniform scale, skew and perspective.
  vec3 h = u_transform * vec3(a_pos.xy, 1.0);
  vec2 hp = h.xy / h.z;
  mat2 jac = mat2(u_transform[0].xy - hp * u_transform[0].z, u_transform[1].xy - hp * u_transform[1].z) / h.z;
  float ss = dot(jac[0], jac[0]) + dot(jac[1], jac[1]);
  float det = abs(jac[0].x * jac[1].y - jac[1].x * jac[0].y);
  float hi = sqrt(0.5 * (ss + sqrt(max(ss * ss - 4.0 * det * det, 0.0))));
  float t = u_fringe_px > 0.0 ? u_fringe_px * hi / max(det, 1e-30) : 0.0;
  vec2 p = a_pos.xy + a_pos.zw * t;
  // Decode (corner, side); code is a small exact integer, so +0.5 keeps the
  // division off the rounding boundaries.
  float side = floor((a_info.x + 0.5) / 3.0);
  float corner = a_info.x - 3.0 * side;
  vec2 tau = vec2(corner > 0.5 && corner < 1.5 ? 1.0 : 0.0, corner > 1.5 ? 1.0 : 0.0);
  float s = side < 0.5 ? 0.0 : (side < 1.5 ? 1.0 : -1.0);
  // The barycentrics are affine: their values at the moved vertex.
  v_coef = vec4(tau + a_info.zw * t, s, 0.0);
  v_info = vec4(side < 0.5 ? 0.0 : 2.0, a_info.y, 0.0, 0.0);
  vec3 q = u_transform * vec3(p, 1.0);
  // Homogeneous clip coordinates: the GPU divides by q.z after clipping and
  // interpolates the varyings perspective-correctly (affine in outline units).
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, 0.0, q.z);
}
