// Second pass of vbaa / msaa: a screen-aligned quad over the block's
// projected bounding box (GLSL ES 1.00; preamble added at compile time).
precision highp float;
attribute vec2 a_clip;  // clip-space corner of the quad
void main() { gl_Position = vec4(a_clip, 0.0, 1.0); }
