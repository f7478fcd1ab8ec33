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
uniform float u_kind;  // 0 linear, 1 radial, 2 sweep
uniform float u_spread;  // 0 pad, 1 reflect, 2 repeat
uniform vec2 u_a;  // linear: start; radial: focus; sweep: centre
uniform vec2 u_b;  // linear: end; radial: centre; sweep: start and end angles (radians)
uniform float u_radius;        // radial: the circle's at t = 1
uniform float u_focal_radius;  // radial: the focus's at t = 0
uniform float u_count;
uniform vec4 u_stop_color[16];  // straight alpha
uniform float u_stop_offset[16];

// The gradient's t at p in .x; .y is 0 where no circle of a radial
// gradient passes through p (the pixel is then transparent).
vec2 gradient_t(vec2 p) {
  if (u_kind < 0.5) {
    vec2 d = u_b - u_a;
    return vec2(dot(p - u_a, d) / dot(d, d), 1.0);
  }
  if (u_kind > 1.5) {
    // Angles in [0, 2 pi) from +x towards +y.
    vec2 q = p - u_a;
    float angle = atan(q.y, q.x);
    if (angle < 0.0) angle += 6.283185307179586;
    return vec2((angle - u_b.x) / (u_b.y - u_b.x), 1.0);
  }
  // Circles c(t) = f + t (c - f), r(t) = r0 + t (r1 - r0): the largest t
  // with |p - c(t)| = r(t) and r(t) >= 0, a root of A t^2 - 2 B t + C = 0.
  vec2 cd = u_b - u_a;
  vec2 pd = p - u_a;
  float dr = u_radius - u_focal_radius;
  float a = dot(cd, cd) - dr * dr;
  float b = dot(pd, cd) + u_focal_radius * dr;
  float c = dot(pd, pd) - u_focal_radius * u_focal_radius;
  if (abs(a) < 1e-6 * (dot(cd, cd) + dr * dr)) {
    // The circles touch the cone's apex at infinity: one root.
    if (b == 0.0) return vec2(0.0, 0.0);
    float t = c / (2.0 * b);
    return vec2(t, step(0.0, u_focal_radius + t * dr));
  }
  float disc = b * b - a * c;
  if (disc < 0.0) return vec2(0.0, 0.0);
  float s = sqrt(disc);
  float t0 = (b + s) / a, t1 = (b - s) / a;
  float hi = max(t0, t1), lo = min(t0, t1);
  if (u_focal_radius + hi * dr >= 0.0) return vec2(hi, 1.0);
  if (u_focal_radius + lo * dr >= 0.0) return vec2(lo, 1.0);
  return vec2(0.0, 0.0);
}

vec4 paint(vec2 pixel) {
  vec3 h = u_paint * vec3(pixel, 1.0);
  vec2 tv = gradient_t(h.xy / h.z);
  if (tv.y == 0.0) return vec4(0.0);
  float t = tv.x;
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
