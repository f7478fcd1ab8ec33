#include "gpu/gl_state.hpp"

#include <cstdio>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"

namespace curvetext::gpu {

ContextInfo ContextInfo::current() {
  ContextInfo info;
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (version == nullptr) return info;
  info.gles = std::strncmp(version, "OpenGL ES", 9) == 0;
  int major = 0, minor = 0;
  // "OpenGL ES 3.2 Mesa ..." / "OpenGL ES-CM 1.1" / "4.5 (Core Profile) Mesa ..."
  const char* digits = info.gles ? std::strchr(version + 9, ' ') : version;
  if (digits != nullptr && std::sscanf(digits, "%d.%d", &major, &minor) >= 1) info.major = major;
  return info;
}

GlStateBackup::GlStateBackup(const ContextInfo& info) : info_(info) {
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  if (program_ != 0) {
    GLint deleted = GL_FALSE;
    glGetProgramiv(static_cast<GLuint>(program_), GL_DELETE_STATUS, &deleted);
    program_deleted_ = deleted == GL_TRUE;
  }
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer_);
  if (info_.gl3()) {
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fbo_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo_);
    // Texture uploads (glTexImage2D with no data) would read from a bound
    // unpack buffer: it is unbound for curvetext's calls.
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    rasterizer_discard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
    if (info_.gles) primitive_restart_ = glIsEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  } else {
    // Without VAOs the element buffer binding and the attribute arrays are
    // the context's: the application's, which the draw changes.
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &element_buffer_);
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &draw_fbo_);
    read_fbo_ = draw_fbo_;
  }
  for (GLuint i = 0; i < kAttributesUsed; ++i) {
    Attribute& a = attributes_[i];
    // Only the offset's current value is set (a constant where it is not an
    // array); attribute 0's cannot even be queried in a compatibility profile.
    if (i == kConstantAttribute) glGetVertexAttribfv(i, GL_CURRENT_VERTEX_ATTRIB, a.current);
    if (info_.gl3()) continue;  // the rest lives in the VAO, and curvetext draws with its own
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &a.enabled);
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_SIZE, &a.size);
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_TYPE, &a.type);
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &a.normalized);
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &a.stride);
    glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &a.buffer);
    glGetVertexAttribPointerv(i, GL_VERTEX_ATTRIB_ARRAY_POINTER, &a.pointer);
  }
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
  glGetIntegerv(GL_VIEWPORT, viewport_);
  glGetIntegerv(GL_SCISSOR_BOX, scissor_box_);
  glGetIntegerv(GL_BLEND_SRC_RGB, &blend_src_rgb_);
  glGetIntegerv(GL_BLEND_DST_RGB, &blend_dst_rgb_);
  glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_src_alpha_);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_dst_alpha_);
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_equation_rgb_);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_equation_alpha_);
  blend_ = glIsEnabled(GL_BLEND);
  depth_test_ = glIsEnabled(GL_DEPTH_TEST);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
  stencil_test_ = glIsEnabled(GL_STENCIL_TEST);
  cull_face_ = glIsEnabled(GL_CULL_FACE);
  scissor_test_ = glIsEnabled(GL_SCISSOR_TEST);
  glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear_color_);
  glGetIntegerv(GL_PACK_ALIGNMENT, &pack_alignment_);
}

namespace {
void set_enabled(GLenum cap, GLboolean on) {
  if (on)
    glEnable(cap);
  else
    glDisable(cap);
}
}  // namespace

void GlStateBackup::apply_target() const {
  if (info_.gl3()) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fbo_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo_));
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(draw_fbo_));
  }
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glScissor(scissor_box_[0], scissor_box_[1], scissor_box_[2], scissor_box_[3]);
  set_enabled(GL_SCISSOR_TEST, scissor_test_);
  set_enabled(GL_DEPTH_TEST, depth_test_);
  glDepthMask(depth_mask_);
  glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
}

GlStateBackup::~GlStateBackup() {
  // A program the application deleted while it was current lives on only as
  // long as it stays current: once curvetext switched to its own it is gone
  // (its name may even be reused), and binding it again would be
  // GL_INVALID_VALUE. No program is current then, as after the application's
  // own switch away from it.
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  if (current != program_) {
    const auto program = static_cast<GLuint>(program_);
    glUseProgram(program != 0 && !program_deleted_ && glIsProgram(program) ? program : 0);
  }
  if (info_.gl3()) {
    glBindVertexArray(static_cast<GLuint>(vertex_array_));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
    set_enabled(GL_RASTERIZER_DISCARD, rasterizer_discard_);
    if (info_.gles) set_enabled(GL_PRIMITIVE_RESTART_FIXED_INDEX, primitive_restart_);
  }
  for (GLuint i = 0; i < kAttributesUsed; ++i) {
    const Attribute& a = attributes_[i];
    if (!info_.gl3()) {
      glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(a.buffer));
      glVertexAttribPointer(i, a.size, static_cast<GLenum>(a.type), static_cast<GLboolean>(a.normalized), a.stride,
                            a.pointer);
      if (a.enabled)
        glEnableVertexAttribArray(i);
      else
        glDisableVertexAttribArray(i);
    }
    if (i == kConstantAttribute) glVertexAttrib4fv(i, a.current);
  }
  glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
  if (!info_.gl3()) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLuint>(element_buffer_));
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(renderbuffer_));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture0_));
  glActiveTexture(static_cast<GLenum>(active_texture_));
  apply_target();
  glBlendFuncSeparate(static_cast<GLenum>(blend_src_rgb_), static_cast<GLenum>(blend_dst_rgb_),
                      static_cast<GLenum>(blend_src_alpha_), static_cast<GLenum>(blend_dst_alpha_));
  glBlendEquationSeparate(static_cast<GLenum>(blend_equation_rgb_), static_cast<GLenum>(blend_equation_alpha_));
  set_enabled(GL_BLEND, blend_);
  set_enabled(GL_STENCIL_TEST, stencil_test_);
  set_enabled(GL_CULL_FACE, cull_face_);
  glClearColor(clear_color_[0], clear_color_[1], clear_color_[2], clear_color_[3]);
  glPixelStorei(GL_PACK_ALIGNMENT, pack_alignment_);
}

void check_no_pending_error(const char* call) {
  const GLenum pending = glGetError();
  if (pending == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(pending));
  throw Error(ErrorCode::Gl, std::string("GL error ") + code + " was pending when " + call +
                                 " began: an earlier GL call of the application's failed; curvetext did nothing");
}

void read_rgba(const ContextInfo& info, GLuint framebuffer, int width, int height, void* out) {
  GLint pack_buffer = 0, row_length = 0, skip_rows = 0, skip_pixels = 0;
  if (info.gl3()) {
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &row_length);
    glGetIntegerv(GL_PACK_SKIP_ROWS, &skip_rows);
    glGetIntegerv(GL_PACK_SKIP_PIXELS, &skip_pixels);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out);
  if (info.gl3()) {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
    glPixelStorei(GL_PACK_ROW_LENGTH, row_length);
    glPixelStorei(GL_PACK_SKIP_ROWS, skip_rows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, skip_pixels);
  }
}

BufferBindingScope::BufferBindingScope(GLenum target, GLuint buffer) : target_(target) {
  glGetIntegerv(target == GL_ELEMENT_ARRAY_BUFFER ? GL_ELEMENT_ARRAY_BUFFER_BINDING : GL_ARRAY_BUFFER_BINDING,
                &previous_);
  glBindBuffer(target, buffer);
}

BufferBindingScope::~BufferBindingScope() { glBindBuffer(target_, static_cast<GLuint>(previous_)); }

}  // namespace curvetext::gpu
