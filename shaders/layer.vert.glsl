// Compositing an offscreen layer (layers.cpp): a quad over the whole
// viewport, the layer's texels one to one with its pixels (GLSL ES 1.00;
// preamble added at compile time).
precision highp float;
attribute vec2 a_clip;  // clip-space corner of the viewport
varying vec2 v_uv;
void main() {
  v_uv = a_clip * 0.5 + 0.5;
  gl_Position = vec4(a_clip, 0.0, 1.0);
}
