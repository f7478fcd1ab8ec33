// Colour bitmaps, fragment stage: the atlas sampled linearly (premultiplied
// sRGB texels, so filtering does not darken edges), times the opacity; into
// a framebuffer that blends in linear light, converted to it first.
precision highp float;

uniform sampler2D u_texture;
uniform float u_opacity;  // DrawOptions::color's alpha
uniform float u_linear;   // 1: the target blends in linear light

varying vec2 v_uv;

void main() {
  vec4 c = texture2D(u_texture, v_uv);
  if (u_linear > 0.5 && c.a > 0.0) {
    vec3 s = clamp(c.rgb / c.a, 0.0, 1.0);
    vec3 lo = s / 12.92;
    vec3 hi = pow((s + 0.055) / 1.055, vec3(2.4));
    c.rgb = mix(lo, hi, step(0.04045, s)) * c.a;
  }
  gl_FragColor = c * u_opacity;
}
