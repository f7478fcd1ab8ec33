// Second pass of full antialiasing (and msaa): puts a tile's coverage, one
// texel per pixel in the red channel of a texture drawn by the first pass, into the
// target with the text's colour. One fetch per pixel. Compiled with
// CURVETEXT_BOX 1, vbaa's box filter instead: the mean of the r x r texels
// under the pixel, without the ring's weights and loop bounds of the filter
// with a ring (resolve.frag.glsl), which a software rasteriser pays for
// every pixel. Compiled with CURVETEXT_PAINT 1, a gradient's colour at each
// pixel instead of u_color: the gradient evaluated at the pixel's centre,
// stops interpolated in straight alpha, then premultiplied (lib/gpu/paint.cpp
// sets its uniforms). Vertex stage: resolve.vert.glsl; lib/gpu/renderer.cpp
// draws one quad per tile.
precision highp float;

uniform sampler2D u_texture;
uniform vec2 u_texture_size;  // texels allocated (the tile may use fewer)
uniform vec2 u_rect_origin;   // framebuffer pixel (x, y down) of the tile's top-left texel
uniform float u_rows;         // texel rows the tile uses (its top row is GL row u_rows - 1)
uniform vec4 u_color;         // premultiplied
uniform float u_coverage_exponent;  // 1 / gamma, in the program compiled with CURVETEXT_GAMMA 1
uniform float u_r;                  // CURVETEXT_BOX: texels per pixel, 1..8

varying vec2 v_pixel;  // framebuffer pixels, y down: the pixel's centre

#if CURVETEXT_PAINT
uniform mat3 u_paint;  // framebuffer pixel (x, y down, 1) -> gradient coordinates (homogeneous)
uniform float u_kind;  // 0 linear, 1 radial
uniform float u_spread;  // 0 pad, 1 reflect, 2 repeat
uniform vec2 u_a;  // linear: start; radial: focus
uniform vec2 u_b;  // linear: end; radial: centre
uniform float u_radius;
uniform float u_count;
uniform vec4 u_stop_color[16];  // straight alpha
uniform float u_stop_offset[16];

// t of the gradient at p; negative when a radial gradient has no circle there.
float gradient_t(vec2 p) {
  if (u_kind < 0.5) {
    vec2 d = u_b - u_a;
    return dot(p - u_a, d) / dot(d, d);
  }
  // The largest t with |p - f - t (c - f)| = t r (circles from the focus f).
  vec2 cd = u_b - u_a;
  vec2 pd = p - u_a;
  float a = dot(cd, cd) - u_radius * u_radius;  // < 0: the focus is inside
  float b = dot(pd, cd);
  float c = dot(pd, pd);
  float disc = max(b * b - a * c, 0.0);
  return (b - sqrt(disc)) / a;
}

vec4 paint(vec2 pixel) {
  vec3 h = u_paint * vec3(pixel, 1.0);
  float t = gradient_t(h.xy / h.z);
  if (u_spread > 1.5) {
    t = fract(t);
  } else if (u_spread > 0.5) {
    t = mod(t, 2.0);
    if (t > 1.0) t = 2.0 - t;
  } else {
    t = clamp(t, 0.0, 1.0);
  }
  vec4 color = u_stop_color[0];
  for (int i = 1; i < 16; ++i) {
    if (float(i) >= u_count) break;
    if (t >= u_stop_offset[i]) {
      color = u_stop_color[i];
      continue;
    }
    float span = u_stop_offset[i] - u_stop_offset[i - 1];
    if (t > u_stop_offset[i - 1] && span > 0.0)
      color = mix(u_stop_color[i - 1], u_stop_color[i], (t - u_stop_offset[i - 1]) / span);
    break;
  }
  return vec4(color.rgb * color.a, color.a);
}
#endif

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
#if CURVETEXT_PAINT
  gl_FragColor = paint(v_pixel) * coverage;
#else
  gl_FragColor = u_color * coverage;
#endif
}
