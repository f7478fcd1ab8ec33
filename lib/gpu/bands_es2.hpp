// Private interface of gpu/ for the library and its tests: the band path on
// OpenGL ES 2.0 contexts (docs/design.md section 9), where the fragment
// shader has high precision and float textures exist. The same bands as on
// GLES 3 (bands.hpp), read with texture2D at texel centres (NEAREST) and
// float indices, in a loop of constant bound (shaders/bands_es2.frag.glsl);
// each placed glyph's quad expanded into 4 vertices carrying the glyph's
// attributes, drawn with a shared index buffer (no instancing).
#pragma once

#include <span>
#include <vector>

#include <GLES2/gl2.h>

#include "gpu/bands.hpp"

namespace curvetext::gpu {

// Whether the current context takes the GLES 2 band path: an OpenGL ES 2.0
// context (no instancing, no texelFetch) whose fragment shaders have highp
// floats that hold integers to 2^24 (precision >= 23 bits, range 2^62) and
// that has OES_texture_float; and the path is not switched off (below).
// Elsewhere on GLES 2 the mesh path draws, as before.
bool es2_band_context();
// Switches the GLES 2 band path off (false) or back on, for every context of
// the process: the tests' way to the fallback on a context that has it.
void set_es2_bands_allowed(bool allowed);

// The most entries any band of `bands` lists (band 0 holds every piece).
int most_band_entries(const GlyphBands& bands);

// Floats per vertex of a GLES 2 band quad: the corner (2), the glyph's box
// (4), its offset, first texel and levels (4), as the instance carries them.
inline constexpr int kBandQuadVertexFloats = 10;
// Glyphs one draw reaches with 16-bit indices (4 vertices each).
inline constexpr int kBandQuadsPerDraw = 16384;
// The 4 vertices of each instance (8 floats: box, place) in `instances`.
std::vector<float> expand_band_quads(std::span<const float> instances);
// An index buffer of kBandQuadsPerDraw quads (two triangles each), made in
// the current context; the caller deletes it.
GLuint make_band_quad_indices();
// Draws quads first .. first + count - 1 of the bound vertex buffer (the
// index buffer bound), attributes 0 .. 2 enabled by the caller.
void draw_band_quads(GLint first, GLsizei count);

}  // namespace curvetext::gpu
