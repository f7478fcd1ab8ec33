// An offscreen RGBA8 framebuffer to draw an image into, and reading it back
// as straight-alpha RGBA.
#include "curvetext/image_target.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/gl_util.hpp"

namespace curvetext {

struct ImageTarget::Impl {
  gpu::ContextInfo info;
  GLuint framebuffer = 0, texture = 0;
  int width = 0, height = 0;
  Blending blending = Blending::Srgb;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { release(); }
  void release() {
    if (framebuffer != 0) glDeleteFramebuffers(1, &framebuffer);
    if (texture != 0) glDeleteTextures(1, &texture);
    framebuffer = texture = 0;
    width = height = 0;
  }
  void allocate(int w, int h, Blending b);
};

namespace {

void check_size(int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0) throw Error(ErrorCode::InvalidArgument, "image size " + size + " must be positive");
  GLint max_texture = 0, max_renderbuffer = 0, max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  int limit = std::min({max_texture, max_renderbuffer, max_viewport[0], max_viewport[1]});
  limit = std::min(limit, static_cast<int>(tolerance::kMaxImageSidePx));
  if (width > limit || height > limit) {
    throw Error(ErrorCode::InvalidArgument,
                "image size " + size + " exceeds the GL maximum of " + std::to_string(limit) + " pixels per side");
  }
}

}  // namespace

// The texture and framebuffer; the caller's state backup puts the bindings back.
void ImageTarget::Impl::allocate(int w, int h, Blending b) {
  release();
  // RGBA/UNSIGNED_BYTE is colour-renderable in every GLES2 implementation.
  // Linear blending: an sRGB texture, which GL decodes before blending and
  // encodes after (always on in GLES 3; desktop GL needs GL_FRAMEBUFFER_SRGB).
  texture = gpu::new_texture(b == Blending::Linear ? GL_SRGB8_ALPHA8 : GL_RGBA, GL_RGBA, w, h);
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    release();
    throw Error(ErrorCode::Gl, "cannot allocate a " + std::to_string(w) + "x" + std::to_string(h) +
                                   " framebuffer texture (GL error " + gpu::hex(err) + ")");
  }
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw Error(ErrorCode::Gl, "offscreen framebuffer incomplete (status " + gpu::hex(status) + ")");
  }
  width = w;
  height = h;
  blending = b;
}

ImageTarget::ImageTarget() : impl_(std::make_unique<Impl>()) {}
ImageTarget::~ImageTarget() = default;
int ImageTarget::width() const { return impl_->width; }
int ImageTarget::height() const { return impl_->height; }
Blending ImageTarget::blending() const { return impl_->blending; }

void ImageTarget::begin(int width, int height, Color background, Blending blending) {
  Impl& t = *impl_;
  if (glGetString(GL_VERSION) == nullptr) {
    throw Error(ErrorCode::Gl, "no current GL context (create a HeadlessContext or make one current)");
  }
  check_size(width, height);
  gpu::check_no_pending_error("ImageTarget::begin");
  if (t.framebuffer == 0) t.info = gpu::ContextInfo::current();
  // The framebuffer bound may be this target's, about to be replaced: not
  // one to bind again afterwards.
  GLint bound = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  const bool remake = t.framebuffer == 0 || t.width != width || t.height != height || t.blending != blending;
  if (remake && t.framebuffer != 0 && static_cast<GLuint>(bound) == t.framebuffer) glBindFramebuffer(GL_FRAMEBUFFER, 0);
  {
    // Everything but the framebuffer binding and viewport this sets up comes
    // back as the application had it.
    const gpu::GlStateBackup state(t.info);
    if (remake) t.allocate(width, height, blending);
    if (!t.info.gles) {
      constexpr GLenum kFramebufferSrgb = 0x8DB9;  // GL_FRAMEBUFFER_SRGB (desktop GL only)
      if (blending == Blending::Linear)
        glEnable(kFramebufferSrgb);
      else
        glDisable(kFramebufferSrgb);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const std::array<float, 4> bg = gpu::premultiplied(background, blending);
    glClearColor(bg[0], bg[1], bg[2], bg[3]);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  glViewport(0, 0, width, height);
}

namespace {

// A premultiplied stored pixel as straight alpha (decoded, divided and
// encoded again where the stored values are sRGB of linear light).
void unpremultiply(const std::uint8_t* src, std::uint8_t* dst, Blending blending) {
  const unsigned a = src[3];
  for (std::size_t k = 0; k < 3; ++k) {
    unsigned v = src[k];
    if (a == 0) {
      v = 0;
    } else if (a < 255 && blending == Blending::Linear) {
      const float lin = gpu::srgb_to_linear(src[k] / 255.0f) * 255.0f / static_cast<float>(a);
      v = static_cast<unsigned>(std::lround(std::clamp(gpu::linear_to_srgb(std::min(lin, 1.0f)), 0.0f, 1.0f) * 255.0f));
    } else if (a < 255) {
      v = std::min(255u, (v * 255u + a / 2u) / a);
    }
    dst[k] = static_cast<std::uint8_t>(v);
  }
  dst[3] = static_cast<std::uint8_t>(a);
}

}  // namespace

Image ImageTarget::read_pixels() const {
  const Impl& t = *impl_;
  if (t.framebuffer == 0) throw Error(ErrorCode::InvalidArgument, "ImageTarget::read_pixels needs begin() first");
  gpu::check_no_pending_error("ImageTarget::read_pixels");
  const gpu::GlStateBackup state(t.info);
  Image gl_rows(t.width, t.height);
  gpu::read_rgba(t.info, t.framebuffer, t.width, t.height, gl_rows.rgba.data());
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "glReadPixels failed (GL error " + gpu::hex(err) + ")");
  }
  Image out(t.width, t.height);
  const std::size_t row = static_cast<std::size_t>(t.width) * 4;
  for (int y = 0; y < t.height; ++y) {
    // GL's row 0 is the bottom; the renderer puts pixel row 0 at the top (clip y = +1).
    const std::uint8_t* src = &gl_rows.rgba[static_cast<std::size_t>(t.height - 1 - y) * row];
    std::uint8_t* dst = &out.rgba[static_cast<std::size_t>(y) * row];
    for (std::size_t i = 0; i < row; i += 4) unpremultiply(src + i, dst + i, t.blending);
  }
  return out;
}

}  // namespace curvetext
