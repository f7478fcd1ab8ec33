// One direction of a separable Gaussian blur of a coverage texture (its
// alpha), times a premultiplied colour: the discrete kernel
// w_k = exp(-k^2 / (2 sigma^2)) for |k| <= radius, normalised to sum 1,
// sampled at texel centres (nearest filtering, edges clamped).
precision highp float;
uniform sampler2D u_texture;
uniform vec2 u_step;    // one texel along the blur's direction, in texture coordinates
uniform float u_sigma;  // texels; the radius is 0 when it is 0
uniform float u_radius; // texels, an integer, at most CURVETEXT_MAX_BLUR_RADIUS
uniform vec4 u_color;   // premultiplied
varying vec2 v_uv;
void main() {
  float sum = texture2D(u_texture, v_uv).a;
  float total = 1.0;
  float inv = u_sigma > 0.0 ? -0.5 / (u_sigma * u_sigma) : 0.0;
  for (int i = 1; i <= CURVETEXT_MAX_BLUR_RADIUS; ++i) {
    float k = float(i);
    if (k > u_radius) break;
    float w = exp(k * k * inv);
    sum += w * (texture2D(u_texture, v_uv + k * u_step).a + texture2D(u_texture, v_uv - k * u_step).a);
    total += 2.0 * w;
  }
  gl_FragColor = u_color * (sum / total);
}
