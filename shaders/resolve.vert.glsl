// Second pass of vbaa / msaa: a screen-aligned quad over the block's
// projected bounding box (GLSL ES 1.00; preamble added at compile time).
precision highp float;
attribute vec2 a_clip;   // clip-space corner of the quad
attribute vec2 a_pixel;  // the same corner in framebuffer pixels (x right, y down)
uniform vec3 u_depth;    // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)
// Pixel position for the fragment stage in highp: GLSL ES 1.00 declares
// gl_FragCoord mediump, and a driver that lowers mediump to 16-bit floats
// (llvmpipe does) rounds x + 0.5 to even above 1024 px, so every odd column
// there would read its neighbour's texels.
varying vec2 v_pixel;
void main() {
  v_pixel = a_pixel;
  gl_Position = vec4(a_clip, dot(u_depth, vec3(a_pixel, 1.0)), 1.0);
}
