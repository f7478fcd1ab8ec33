#include "gpu/gl_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "curvetext/error.hpp"

namespace curvetext::gpu {

std::string hex(GLenum e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(e));
  return buf;
}

GLuint new_texture(GLint internal_format, GLenum format, int w, int h) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, w, h, 0, format, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

std::array<float, 4> premultiplied(const Color& c, Blending blending) {
  const float a = std::clamp(c.a, 0.0f, 1.0f);
  std::array<float, 4> out{std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f), a};
  for (int i = 0; i < 3; ++i) {
    if (blending == Blending::Linear) out[i] = srgb_to_linear(out[i]);
    out[i] *= a;
  }
  return out;
}

Blending bound_framebuffer_blending(bool gles, bool gl3, GLuint draw_framebuffer) {
  if (!gl3) return Blending::Srgb;
  constexpr GLenum kFramebufferSrgb = 0x8DB9;  // GL_FRAMEBUFFER_SRGB (desktop GL only)
  if (!gles && !glIsEnabled(kFramebufferSrgb)) return Blending::Srgb;
  // The default framebuffer's colour buffer is GL_BACK on GLES, GL_BACK_LEFT on desktop GL.
  constexpr GLenum kBackLeft = 0x0402;
  const GLenum attachment = draw_framebuffer != 0 ? GL_COLOR_ATTACHMENT0 : (gles ? GL_BACK : kBackLeft);
  GLint type = GL_NONE, encoding = GL_LINEAR;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_NONE)
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
                                          &encoding);
  glGetError();  // a framebuffer without that attachment: not sRGB
  return encoding == GL_SRGB ? Blending::Linear : Blending::Srgb;
}

std::string glsl1_preamble(GLenum type, bool gles) {
  if (gles) return "#version 100\n";
  std::string p = "#version 330 core\n#define texture2D texture\n";
  if (type == GL_VERTEX_SHADER) {
    p += "#define attribute in\n#define varying out\n";
  } else {
    p += "#define varying in\nout vec4 curvetext_frag_color;\n#define gl_FragColor curvetext_frag_color\n";
  }
  return p;
}

namespace {

std::string info_log(GLuint object, bool program) {
  GLint len = 0;
  if (program) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  }
  std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
  if (program) {
    glGetProgramInfoLog(object, len, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, len, nullptr, log.data());
  }
  log.resize(std::strlen(log.c_str()));
  std::replace(log.begin(), log.end(), '\n', ' ');
  return log;
}

GLuint glsl1_shader(GLenum type, const char* source, bool gles, const std::string& defines, const char* what) {
  const std::string text = glsl1_preamble(type, gles) + defines + source;
  const GLuint shader = glCreateShader(type);
  if (shader == 0) throw Error(ErrorCode::Gl, std::string(what) + ": glCreateShader failed");
  const char* src = text.c_str();
  glShaderSource(shader, 1, &src, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw Error(ErrorCode::Gl, std::string(what) + (type == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                                   " shader failed to compile: " + log);
  }
  return shader;
}

}  // namespace

GLuint glsl1_program(const char* vertex, const char* fragment, bool gles, std::initializer_list<const char*> attributes,
                     const char* what, const std::string& defines) {
  const GLuint vs = glsl1_shader(GL_VERTEX_SHADER, vertex, gles, defines, what);
  GLuint fs = 0;
  try {
    fs = glsl1_shader(GL_FRAGMENT_SHADER, fragment, gles, defines, what);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  GLuint location = 0;
  for (const char* name : attributes) glBindAttribLocation(program, location++, name);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(program, true);
    glDeleteProgram(program);
    throw Error(ErrorCode::Gl, std::string(what) + " failed to link: " + log);
  }
  return program;
}

}  // namespace curvetext::gpu
