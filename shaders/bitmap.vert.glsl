// Colour bitmaps (CBDT/sbix emoji), vertex stage: textured quads from the
// glyph cache's atlas (lib/gpu/color_bitmaps.cpp), placed as the curve
// shader places meshes (curve.vert.glsl), without growth.
precision highp float;

attribute vec4 a_vertex;  // (x, y) outline units, (u, v) atlas texture coordinates

uniform mat3 u_transform;  // outline units -> framebuffer pixels, y down (projective)
uniform vec2 u_viewport;   // framebuffer size in pixels
uniform vec3 u_depth;      // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)

varying vec2 v_uv;

void main() {
  v_uv = a_vertex.zw;
  vec3 q = u_transform * vec3(a_vertex.xy, 1.0);
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, dot(u_depth, q), q.z);
}
