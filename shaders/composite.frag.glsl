// Second pass of full antialiasing (and msaa): puts a tile's coverage, one
// texel per pixel in the red channel of a texture drawn by the first pass, into the
// target with the text's colour. One fetch per pixel. Compiled with
// CURVETEXT_BOX 1, vbaa's box filter instead: the mean of the r x r texels
// under the pixel, without the ring's weights and loop bounds of the filter
// with a ring (resolve.frag.glsl), which a software rasteriser pays for
// every pixel. Vertex stage: resolve.vert.glsl; lib/gpu/renderer.cpp draws
// one quad per tile.
precision highp float;

uniform sampler2D u_texture;
uniform vec2 u_texture_size;  // texels allocated (the tile may use fewer)
uniform vec2 u_rect_origin;   // framebuffer pixel (x, y down) of the tile's top-left texel
uniform float u_rows;         // texel rows the tile uses (its top row is GL row u_rows - 1)
uniform vec4 u_color;         // premultiplied
uniform float u_coverage_exponent;  // 1 / gamma, in the program compiled with CURVETEXT_GAMMA 1
uniform float u_r;                  // CURVETEXT_BOX: texels per pixel, 1..8

varying vec2 v_pixel;  // framebuffer pixels, y down: the pixel's centre

void main() {
#if CURVETEXT_BOX
  // The pixel's texel block: columns from px r, rows (down) from py r, GL
  // rows up from u_rows - 1.
  float px = floor(v_pixel.x) - u_rect_origin.x;
  float py = floor(v_pixel.y) - u_rect_origin.y;
  float sum = 0.0;
  for (int j = 0; j < 8; ++j) {
    if (float(j) >= u_r) break;
    for (int i = 0; i < 8; ++i) {
      if (float(i) >= u_r) break;
      vec2 texel = vec2(px * u_r + float(i), u_rows - 1.0 - (py * u_r + float(j)));
      sum += texture2D(u_texture, (texel + 0.5) / u_texture_size).r;
    }
  }
  float coverage = sum / (u_r * u_r);
#else
  vec2 t = v_pixel - u_rect_origin;
  float coverage = texture2D(u_texture, vec2(t.x, u_rows - t.y) / u_texture_size).r;  // r: every channel of an RGBA target holds it
#endif
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  gl_FragColor = u_color * coverage;
}
