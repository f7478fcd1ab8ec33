// The composite pass (composite.frag.glsl) with a gradient's colour at each
// pixel instead of one colour: the pixel's coverage (one fetch, or vbaa's
// box filter with CURVETEXT_BOX) times the gradient evaluated at the pixel's
// centre. Stops are interpolated in straight alpha, then premultiplied. lib/gpu/paint.cpp sets the
// paint's uniforms; lib/gpu/renderer.cpp draws one quad per tile.
precision highp float;

uniform sampler2D u_texture;
uniform vec2 u_texture_size;
uniform vec2 u_rect_origin;
uniform float u_rows;
uniform float u_coverage_exponent;
uniform float u_r;

uniform mat3 u_paint;  // framebuffer pixel (x, y down, 1) -> gradient coordinates (homogeneous)
uniform float u_kind;  // 0 linear, 1 radial
uniform float u_spread;  // 0 pad, 1 reflect, 2 repeat
uniform vec2 u_a;  // linear: start; radial: focus
uniform vec2 u_b;  // linear: end; radial: centre
uniform float u_radius;
uniform float u_count;
uniform vec4 u_stop_color[16];  // straight alpha
uniform float u_stop_offset[16];

varying vec2 v_pixel;

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

void main() {
#if CURVETEXT_BOX
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
  float coverage = texture2D(u_texture, vec2(t.x, u_rows - t.y) / u_texture_size).r;
#endif
  if (coverage <= 0.0) discard;
#if CURVETEXT_GAMMA
  coverage = pow(coverage, u_coverage_exponent);
#endif
  gl_FragColor = paint(v_pixel) * coverage;
}
