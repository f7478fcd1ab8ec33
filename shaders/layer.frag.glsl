// An offscreen layer (premultiplied) composited at an opacity (layers.cpp):
// source-over for SVG's group opacity, or, blended as dst * src.a, a clip
// mask's coverage multiplied into the layer under it.
precision highp float;
uniform sampler2D u_texture;
uniform float u_opacity;
varying vec2 v_uv;
void main() {
  gl_FragColor = texture2D(u_texture, v_uv) * u_opacity;
}
