// The application's GL state around curvetext's calls (docs/design.md section 5):
// everything a draw may change is read first and put back afterwards, also
// when the call throws, as Dear ImGui's GL backends do. Private to the library.
#pragma once

#include <GLES3/gl3.h>

namespace curvetext::gpu {

// What the current context offers that the state depends on.
struct ContextInfo {
  bool gles = true;
  int major = 2;
  bool gl3() const { return major >= 3; }  // VAOs, draw/read framebuffers, instancing (GLES 3, GL 3.3)
  static ContextInfo current();            // from GL_VERSION of the current context
};

// The vertex attributes curvetext's programs use (locations 0 .. 2).
inline constexpr GLuint kAttributesUsed = 3;
// The one of them curvetext may give a constant value (glVertexAttrib*).
inline constexpr GLuint kConstantAttribute = 2;

// Reads the state at construction and restores it at destruction.
class GlStateBackup {
 public:
  explicit GlStateBackup(const ContextInfo& info);
  ~GlStateBackup();
  GlStateBackup(const GlStateBackup&) = delete;
  GlStateBackup& operator=(const GlStateBackup&) = delete;

  // The application's target as it was: framebuffer, viewport, scissor,
  // depth test and depth writes, and colour mask (the composite pass draws
  // there after an offscreen pass changed them).
  void apply_target() const;
  GLuint draw_framebuffer() const { return static_cast<GLuint>(draw_fbo_); }
  const GLint* viewport() const { return viewport_; }

 private:
  struct Attribute {
    GLint enabled = 0, size = 4, type = GL_FLOAT, normalized = 0, stride = 0, buffer = 0;
    void* pointer = nullptr;
    GLfloat current[4] = {0, 0, 0, 1};
  };
  ContextInfo info_;
  bool program_deleted_ = false;  // flagged for deletion by the application while current
  GLint program_ = 0, array_buffer_ = 0, element_buffer_ = 0, vertex_array_ = 0, renderbuffer_ = 0;
  GLint draw_fbo_ = 0, read_fbo_ = 0, unpack_buffer_ = 0;
  GLint active_texture_ = 0, texture0_ = 0;
  GLint viewport_[4] = {0, 0, 0, 0}, scissor_box_[4] = {0, 0, 0, 0};
  GLint blend_src_rgb_ = 0, blend_dst_rgb_ = 0, blend_src_alpha_ = 0, blend_dst_alpha_ = 0;
  GLint blend_equation_rgb_ = 0, blend_equation_alpha_ = 0;
  GLboolean blend_ = 0, depth_test_ = 0, depth_mask_ = 1, stencil_test_ = 0, cull_face_ = 0, scissor_test_ = 0;
  GLboolean primitive_restart_ = 0, rasterizer_discard_ = 0;
  GLboolean color_mask_[4] = {1, 1, 1, 1};
  GLfloat clear_color_[4] = {0, 0, 0, 0};
  GLint pack_alignment_ = 4;
  Attribute attributes_[kAttributesUsed];
};

// A GL error pending when a call of curvetext's begins is the application's:
// throws Error(Gl) saying so (naming `call`), before anything is changed.
void check_no_pending_error(const char* call);

// Reads width x height RGBA8 pixels of `framebuffer` into `out`, tightly
// packed, whatever pack state (alignment, row length, pack buffer) the
// application set; that state comes back afterwards.
void read_rgba(const ContextInfo& info, GLuint framebuffer, int width, int height, void* out);

// Binds `buffer` to `target` for an upload and puts the previous binding back
// (an element buffer binding belongs to the application's bound VAO).
class BufferBindingScope {
 public:
  BufferBindingScope(GLenum target, GLuint buffer);
  ~BufferBindingScope();
  BufferBindingScope(const BufferBindingScope&) = delete;
  BufferBindingScope& operator=(const BufferBindingScope&) = delete;

 private:
  GLenum target_;
  GLint previous_ = 0;
};

// Binds a texture for an upload with tightly packed rows, and puts the
// application's binding (of the active unit) and unpack state back.
class TextureUploadScope {
 public:
  explicit TextureUploadScope(GLuint texture) : info_(ContextInfo::current()) {
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment_);
    if (info_.gl3()) {
      glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length_);
      glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skip_rows_);
      glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip_pixels_);
      glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
      glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, texture);
  }
  ~TextureUploadScope() {
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment_);
    if (info_.gl3()) {
      glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length_);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows_);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels_);
      glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
    }
  }
  TextureUploadScope(const TextureUploadScope&) = delete;
  TextureUploadScope& operator=(const TextureUploadScope&) = delete;

 private:
  ContextInfo info_;
  GLint texture_ = 0, alignment_ = 4, row_length_ = 0, skip_rows_ = 0, skip_pixels_ = 0, unpack_buffer_ = 0;
};

}  // namespace curvetext::gpu
