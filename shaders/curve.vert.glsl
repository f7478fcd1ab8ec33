// Curve shader, vertex stage (GLSL ES 1.00; a preamble added at compile time
// selects #version 100 or desktop 330 core), shared by the single-pass modes
// (curve.frag.glsl) and full antialiasing (area.frag.glsl). Vertex layout:
// lib/gpu/vertex_format.hpp.
precision highp float;

attribute vec4 a_pos;   // (x, y, ax, ay): the corner, the edge to the next corner (outline units)
attribute vec4 a_info;  // (alpha, beta, code, w): the edge to the previous corner in a's frame, what the point is, the weight
attribute vec2 a_offset;  // the glyph's placement in the block (outline units; per instance, or 0)

uniform mat3 u_transform;     // outline units -> framebuffer pixels, y down (projective)
uniform vec2 u_viewport;      // framebuffer size in pixels
uniform float u_fringe_px;    // the most growth in pixels (0: the triangles as they are)
uniform vec3 u_depth;         // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)

varying vec4 v_coef;  // (tau1, tau2, s, 0): barycentrics; s +1 convex curve, -1 concave, 0 interior
varying vec4 v_info;  // (kind, w, 0, 0): kind 0 interior, 2 curved; w the conic weight

void main() {
  // Dilation in outline units. The smallest stretch of u_transform at this
  // vertex (the smaller singular value of its Jacobian) turns pixels into
  // outline units, so every edge moves out by at least its reach in pixels
  // (below) under rotation, non-uniform scale, skew and perspective.
  // Shared corners of neighbouring triangles add the same offset, so they
  // stay bit-identical (watertight) after it.
  vec2 corner_pos = a_pos.xy + a_offset;
  vec3 h = u_transform * vec3(corner_pos, 1.0);
  vec2 hp = h.xy / h.z;
  mat2 jac = mat2(u_transform[0].xy - hp * u_transform[0].z, u_transform[1].xy - hp * u_transform[1].z) / h.z;
  float ss = dot(jac[0], jac[0]) + dot(jac[1], jac[1]);
  float det = abs(jac[0].x * jac[1].y - jac[1].x * jac[0].y);
  float hi = sqrt(0.5 * (ss + sqrt(max(ss * ss - 4.0 * det * det, 0.0))));
  // Decode code = corner + 3 side + 9 point (a small whole number: +0.5
  // keeps floor and mod off the rounding boundaries).
  float code = a_info.z + 0.5;
  float point = floor(code / 9.0);
  code = mod(code, 9.0);
  float side = floor(code / 3.0);
  float corner = floor(code - 3.0 * side);
  vec2 a = a_pos.zw;  // to the next corner
  vec2 b = a_info.x * a + a_info.y * vec2(-a.y, a.x);  // to the previous corner
  // How far a pixel's box reaches past an edge: half the sum of the absolute
  // components of the edge's direction on screen (0.5 px along the axes,
  // sqrt(2)/2 diagonally). A pixel whose box touches the triangle has its
  // centre within that reach of it, so growing each edge by it gives every
  // such pixel a fragment, and no more than that: most edges of text are
  // near the axes. The corner takes the larger of its two edges' reaches (a
  // bevel's points also its bisector's: the bevel cuts across it), plus a
  // margin for rounding; an edge grown by more at one end stays conservative.
  vec2 ua = jac * a;
  vec2 ub = jac * b;
  ua /= max(length(ua), 1e-30);
  ub /= max(length(ub), 1e-30);
  float reach = max(abs(ua.x) + abs(ua.y), abs(ub.x) + abs(ub.y));
  if (point > 0.5) {
    vec2 bis = ua + ub;
    bis = dot(bis, bis) > 1e-12 ? normalize(bis) : vec2(-ua.y, ua.x);
    reach = max(reach, abs(bis.x) + abs(bis.y));
  }
  reach = 0.5 * reach + 1e-4;
  float t = min(reach, u_fringe_px) * hi / max(det, 1e-30);
  float area2 = a_info.y * dot(a, a);  // doubled signed area of the triangle (p0, p1, p2)
  float ccw = area2 > 0.0 ? 1.0 : -1.0;
  vec2 offset = vec2(0.0);
  vec2 dtau = vec2(0.0);
  if (t > 0.0) {
    // Each edge moves out by t: outward normals of the arriving and leaving
    // edges, meeting at the miter, or at a bevel (two points at distance t
    // along the corner's bisector, one on each moved edge; lib/gpu/pack.cpp).
    vec2 e_in = normalize(-b);  // along the arriving edge, onward
    vec2 e_out = normalize(a);  // along the leaving edge
    vec2 n_in = vec2(e_in.y, -e_in.x) * ccw;
    vec2 n_out = vec2(e_out.y, -e_out.x) * ccw;
    float denom = 1.0 + dot(n_in, n_out);
    if (point < 0.5) {
      offset = (n_in + n_out) / denom;
    } else {
      // With c the cosine of the corner's angle (1 + c = 2 - denom) the
      // unit vectors along the edges away from the corner sum to a bisector
      // of length sqrt(2 (1 + c)), and the point on a moved edge at distance 1
      // along it is as below (pack.cpp's file comment).
      float one_plus_c = 2.0 - denom;
      float bisector = sqrt(2.0 * one_plus_c);
      offset = point < 1.5 ? n_in + e_in * ((bisector + dot(e_out, n_in)) / one_plus_c)
                           : n_out - e_out * ((bisector - dot(e_in, n_out)) / one_plus_c);
    }
    // The barycentrics' gradients from the triangle's edges p1 - p0 and
    // p2 - p0, written with this corner's two edges.
    vec2 e1 = corner < 0.5 ? a : (corner < 1.5 ? -b : b - a);
    vec2 e2 = corner < 0.5 ? b : (corner < 1.5 ? a - b : -a);
    dtau = vec2(dot(vec2(e2.y, -e2.x), offset), dot(vec2(-e1.y, e1.x), offset)) / area2;
  }
  vec2 p = corner_pos + offset * t;
  vec2 tau = vec2(corner > 0.5 && corner < 1.5 ? 1.0 : 0.0, corner > 1.5 ? 1.0 : 0.0);
  float s = side < 0.5 ? 0.0 : (side < 1.5 ? 1.0 : -1.0);
  // The barycentrics are affine: their values at the moved vertex.
  v_coef = vec4(tau + dtau * t, s, 0.0);
  v_info = vec4(side < 0.5 ? 0.0 : 2.0, a_info.w, 0.0, 0.0);
  vec3 q = u_transform * vec3(p, 1.0);
  // Homogeneous clip coordinates: the GPU divides by q.z after clipping and
  // interpolates the varyings perspective-correctly (affine in outline units).
  // z times w is dot(u_depth, q): the depth plane is affine in the pixel position.
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, dot(u_depth, q), q.z);
}
