// One pass exact area on OpenGL ES 2.0 (docs/design.md section 9), vertex
// stage (GLSL ES 1.00; the preamble gives the #version line): bands.vert.glsl
// without instancing. Each placed glyph's quad comes as 4 vertices that
// carry its box and placement (lib/gpu/bands_es2.cpp), grown by half a
// pixel's footprint in outline units as there.
attribute vec2 a_corner;  // (0, 0), (1, 0), (0, 1), (1, 1)
attribute vec4 a_rect;    // the glyph's box, outline units from its origin: (x0, y0, x1, y1)
attribute vec4 a_place;   // (offset x, offset y) in the block, outline units; first texel; levels

uniform mat3 u_transform;  // outline units -> framebuffer pixels, y down (affine here)
uniform vec2 u_viewport;   // framebuffer size in pixels
uniform vec3 u_depth;      // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)
uniform vec2 u_half;       // half a pixel's footprint along x and y, outline units

// The same at the quad's 4 vertices: interpolated, they stay what they are
// (the fragment stage rounds the integers).
varying vec2 v_local;  // this point from the glyph's origin, outline units
varying vec4 v_rect;   // a_rect
varying vec2 v_glyph;  // (first texel, levels)

void main() {
  vec2 local = mix(a_rect.xy - u_half, a_rect.zw + u_half, a_corner);
  v_local = local;
  v_rect = a_rect;
  v_glyph = a_place.zw;
  vec3 q = u_transform * vec3(local + a_place.xy, 1.0);
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, dot(u_depth, q), q.z);
}
