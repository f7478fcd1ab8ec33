// Second pass of full antialiasing (and msaa): puts a tile's coverage, one
// texel per pixel in the red channel of a texture drawn by the first pass, into the
// target with the text's colour. One fetch per pixel. Vertex stage:
// resolve.vert.glsl; lib/gpu/renderer.cpp draws one quad per tile.
precision highp float;

uniform sampler2D u_texture;
uniform vec2 u_texture_size;  // texels allocated (the tile may use fewer)
uniform vec2 u_rect_origin;   // framebuffer pixel (x, y down) of the tile's top-left texel
uniform float u_rows;         // texel rows the tile uses (its top row is GL row u_rows - 1)
uniform vec4 u_color;         // premultiplied
uniform float u_coverage_exponent;  // 1 / gamma, in the program compiled with CURVETEXT_GAMMA 1

varying vec2 v_pixel;  // framebuffer pixels, y down: the pixel's centre

void main() {
  vec2 t = v_pixel - u_rect_origin;
  float coverage = texture2D(u_texture, vec2(t.x, u_rows - t.y) / u_texture_size).r;  // r: every channel of an RGBA target holds it
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  gl_FragColor = u_color * coverage;
}
