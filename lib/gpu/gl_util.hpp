// Small GL and colour helpers the renderer and the image target share.
// Private to the library.
#pragma once

#include <GLES3/gl3.h>

#include <array>
#include <initializer_list>
#include <string>

#include "curvetext/color.hpp"
#include "curvetext/image_target.hpp"

namespace curvetext::gpu {

// A GL enum as 0x%04x, for messages.
std::string hex(GLenum e);

// A new texture of w x h texels, no data, sampled nearest and clamped: the
// library's framebuffers and coverage textures. Leaves no texture bound (the
// caller restores the application's binding).
GLuint new_texture(GLint internal_format, GLenum format, int w, int h);

// The #version line and renames that let a GLSL ES 1.00 shader file (no
// #version of its own) compile as desktop GLSL 3.30 core too.
std::string glsl1_preamble(GLenum type, bool gles);

// A program from two GLSL ES 1.00 shader files, each after the preamble and
// `defines`, its attributes bound to locations 0, 1, ... in the order given.
// Error(Gl) naming `what`, with the compile or link log, on failure; nothing
// is left allocated then.
GLuint glsl1_program(const char* vertex, const char* fragment, bool gles, std::initializer_list<const char*> attributes,
                     const char* what, const std::string& defines = "");

// sRGB transfer functions (IEC 61966-2-1), on values in [0, 1].
float srgb_to_linear(float c);
float linear_to_srgb(float c);

// `c` premultiplied, in the space the framebuffer blends in.
std::array<float, 4> premultiplied(const Color& c, Blending blending);

// How the framebuffer bound for drawing blends: Linear where its colour
// buffer is sRGB-encoded and the context converts (always on GLES 3; on
// desktop GL with GL_FRAMEBUFFER_SRGB enabled). GLES 2: Srgb.
Blending bound_framebuffer_blending(bool gles, bool gl3, GLuint draw_framebuffer);

}  // namespace curvetext::gpu
