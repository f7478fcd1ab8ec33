// One pass exact area (docs/design.md section 9), vertex stage: one quad per
// placed glyph, instanced (GLSL ES 3.00 / 3.30; a preamble added at compile
// time gives the #version line). The quad is the glyph's box grown by half a
// pixel's footprint in outline units, so every pixel whose box meets the
// glyph gets a fragment. Fragment stage: bands.frag.glsl; instance layout:
// lib/gpu/batch.cpp (band_instances).
in vec2 a_corner;  // (0, 0), (1, 0), (0, 1), (1, 1)
in vec4 a_rect;    // the glyph's box, outline units from its origin: (x0, y0, x1, y1)
in vec4 a_place;   // (offset x, offset y) in the block, outline units; first texel; levels

uniform mat3 u_transform;  // outline units -> framebuffer pixels, y down (affine here)
uniform vec2 u_viewport;   // framebuffer size in pixels
uniform vec3 u_depth;      // normalized device z = dot(u_depth, (x_px, y_px, 1)) (Placement::depth)
uniform vec2 u_half;       // half a pixel's footprint along x and y, outline units

out vec2 v_local;         // this point from the glyph's origin, outline units
flat out vec4 v_rect;     // a_rect
flat out vec2 v_glyph;    // (first texel, levels)

#if CURVETEXT_FOOTPRINT
// Under a map that turns the axes (bands.frag.glsl): u_half is half the
// bounding box of a pixel's parallelogram footprint under an affine map;
// under perspective it varies, and the glyph's box grows by its largest at
// the box's corners and centre (first order, as the area is).
uniform mat3 u_inverse;    // framebuffer pixels -> outline units
uniform int u_projective;  // 1: the footprint varies per pixel
flat out vec2 v_offset;    // a_place.xy

vec2 reach_at(vec2 p) {
  float w = dot(vec3(u_transform[0].z, u_transform[1].z, u_transform[2].z), vec3(p, 1.0));
  vec2 u = w * (u_inverse[0].xy - p * u_inverse[0].z);
  vec2 v = w * (u_inverse[1].xy - p * u_inverse[1].z);
  return 0.5 * (abs(u) + abs(v));
}
#endif

void main() {
  vec2 half_box = u_half;
#if CURVETEXT_FOOTPRINT
  v_offset = a_place.xy;
  if (u_projective != 0) {
    vec2 o = a_place.xy;
    half_box = max(max(reach_at(o + a_rect.xy), reach_at(o + a_rect.zw)),
                   max(max(reach_at(o + a_rect.xw), reach_at(o + a_rect.zy)), reach_at(o + 0.5 * (a_rect.xy + a_rect.zw))));
  }
#endif
  vec2 local = mix(a_rect.xy - half_box, a_rect.zw + half_box, a_corner);
  v_local = local;
  v_rect = a_rect;
  v_glyph = a_place.zw;
  vec3 q = u_transform * vec3(local + a_place.xy, 1.0);
  gl_Position = vec4(2.0 * q.x / u_viewport.x - q.z, q.z - 2.0 * q.y / u_viewport.y, dot(u_depth, q), q.z);
}
