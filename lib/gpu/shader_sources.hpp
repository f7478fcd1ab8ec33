// Shader texts embedded at build time from shaders/*.glsl (see
// cmake/EmbedShaders.cmake). The identifier is the file name with '.' -> '_'.
#pragma once

namespace curvetext::shader_source {
extern const char* const curve_vert_glsl;
extern const char* const curve_frag_glsl;
extern const char* const area_frag_glsl;
extern const char* const resolve_vert_glsl;
extern const char* const resolve_frag_glsl;
extern const char* const composite_frag_glsl;
extern const char* const bitmap_vert_glsl;
extern const char* const bitmap_frag_glsl;
extern const char* const bands_vert_glsl;
extern const char* const bands_frag_glsl;
extern const char* const bands_es2_vert_glsl;
extern const char* const bands_es2_frag_glsl;
extern const char* const shadow_vert_glsl;
extern const char* const shadow_frag_glsl;
extern const char* const layer_vert_glsl;
extern const char* const layer_frag_glsl;
}  // namespace curvetext::shader_source
