// Text shadows (lib/gpu/effects.cpp): a pixel-aligned quad over the shadow's
// region, for the horizontal blur pass (offscreen, depth unused) and the
// vertical pass that composites into the application's framebuffer at the
// placement's depth (GLSL ES 1.00; preamble added at compile time).
precision highp float;
attribute vec2 a_pixel;  // corner in pixels of the viewport drawn into (x right, y down)
attribute vec2 a_uv;     // the same corner in the source texture, [0, 1]
uniform vec2 u_viewport;  // its size, pixels
uniform vec3 u_depth;     // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)
varying vec2 v_uv;
void main() {
  v_uv = a_uv;
  vec2 ndc = vec2(2.0 * a_pixel.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pixel.y / u_viewport.y);
  gl_Position = vec4(ndc, dot(u_depth, vec3(a_pixel, 1.0)), 1.0);
}
