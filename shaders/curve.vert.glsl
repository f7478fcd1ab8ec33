// Curve shader, vertex stage (GLSL ES 1.00; a preamble added at compile time
// selects #version 100 or desktop 330 core). Vertex layout: lib/gpu/vertex_format.hpp.
precision highp float;

attribute vec4 a_pos;   // (x, y, ox, oy): outline units, fringe offset per unit of dilation
attribute vec4 a_coef;  // (c0, c1, c2, c3)
attribute vec4 a_info;  // (kind, w or dc2, dc0, dc1)

uniform mat3 u_transform;     // outline units -> framebuffer pixels, y down
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform float u_px_per_unit;  // sqrt|det| of the linear part of u_transform
uniform float u_fringe_px;    // fringe width in pixels (0 unless AA is full)

varying vec4 v_coef;
varying vec2 v_info;  // (kind, weight)

// Vertices shared between triangles must land on identical positions, or
// rasterisation leaves cracks / double-blended pixels along shared edges.
invariant gl_Position;

void main() {
  // Dilation in outline units; 0 makes the fringe triangles zero-area.
  float t = u_fringe_px / u_px_per_unit;
  vec2 p = a_pos.xy + a_pos.zw * t;
  // For edges (kind 1) the weight slot carries the derivative of c2.
  float dc2 = (a_info.x > 0.5 && a_info.x < 1.5) ? a_info.y : 0.0;
  v_coef = a_coef + vec4(a_info.z, a_info.w, dc2, 0.0) * t;
  v_info = a_info.xy;
  vec3 q = u_transform * vec3(p, 1.0);
  gl_Position = vec4(2.0 * q.x / u_viewport.x - 1.0, 1.0 - 2.0 * q.y / u_viewport.y, 0.0, 1.0);
}
