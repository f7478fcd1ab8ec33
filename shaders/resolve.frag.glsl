// Second pass of vbaa: filters the block's coverage, drawn r times
// larger into a texture (its red channel), down to one pixel. The kernel is the
// r x r texels under the pixel (exact area at r x resolution) plus a ring of
// one texel around them weighted u_ring (horizontal and vertical neighbours)
// and u_ring^2 (diagonal ones): the paper's section 5 filter, which weights
// horizontal and vertical neighbours above diagonal ones. u_ring = 0 is a box.
precision highp float;

uniform sampler2D u_texture;
uniform vec2 u_texture_size;  // texels allocated (the tile may use fewer)
uniform vec2 u_rect_origin;   // framebuffer pixel (x, y down) of texel block (0, 0)
uniform float u_rows;         // texel rows the tile uses (its top row is GL row u_rows - 1)
uniform float u_r;            // texels per pixel, 1..8
uniform float u_ring;
uniform vec4 u_color;         // premultiplied
uniform float u_coverage_exponent;  // 1 / gamma, applied after filtering

varying vec2 v_pixel;         // framebuffer pixels, y down (see resolve.vert.glsl)

float weight(float i) { return (i < 0.0 || i >= u_r) ? u_ring : 1.0; }

void main() {
  float px = floor(v_pixel.x) - u_rect_origin.x;
  float py = floor(v_pixel.y) - u_rect_origin.y;  // rows down
  float sum = 0.0;
  float total = 0.0;
  for (int j = -1; j <= 8; ++j) {
    float fj = float(j);
    if (fj > u_r) break;
    for (int i = -1; i <= 8; ++i) {
      float fi = float(i);
      if (fi > u_r) break;
      float w = weight(fi) * weight(fj);
      if (w <= 0.0) continue;
      float col = px * u_r + fi;
      float row = u_rows - 1.0 - (py * u_r + fj);  // GL rows up
      float a = texture2D(u_texture, (vec2(col, row) + 0.5) / u_texture_size).r;  // r: every channel of an RGBA target holds it
      sum += w * a;
      total += w;
    }
  }
  float coverage = sum / total;
  if (coverage <= 0.0) discard;
  gl_FragColor = u_color * (u_coverage_exponent == 1.0 ? coverage : pow(coverage, u_coverage_exponent));
}
