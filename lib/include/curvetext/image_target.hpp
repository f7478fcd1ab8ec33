// An offscreen image to draw into: for programs without a window (the CLI,
// tests, thumbnails), apart from Renderer, which draws into whatever
// framebuffer is bound.
#pragma once

#include <memory>

#include "curvetext/color.hpp"
#include "curvetext/export.hpp"
#include "curvetext/image.hpp"

namespace curvetext {

// How a framebuffer blends.
enum class Blending {
  Srgb,    // on the stored sRGB-encoded values, as most apps do (default)
  Linear,  // in linear light: an sRGB framebuffer decodes, blends and encodes
           // (GLES 3 / desktop GL 3); colours are sRGB and converted
};

// An RGBA8 framebuffer of its own (a texture, sRGB-encoded for
// Blending::Linear). Owns its GL objects: they belong to the context current
// at begin(), which must be current whenever the target is used or
// destroyed. Not thread-safe: one thread (and its context) at a time.
//
//   ImageTarget target;
//   target.begin(640, 480, Color{1, 1, 1, 1});   // bound, viewport on it, cleared
//   renderer.draw(batch, placement, options);     // draws into it
//   Image image = target.read_pixels();
class CURVETEXT_API ImageTarget {
 public:
  ImageTarget();
  ~ImageTarget();
  ImageTarget(const ImageTarget&) = delete;
  ImageTarget& operator=(const ImageTarget&) = delete;

  // Binds the target's framebuffer of width x height pixels (made again when
  // the size or blending changes), sets the viewport to it and clears it to
  // `background`. It stays bound with its viewport (its purpose); the rest of
  // the GL state is left as it was, except that on desktop GL,
  // Blending::Linear enables GL_FRAMEBUFFER_SRGB (and Srgb disables it).
  // Throws Error(InvalidArgument) for a size that is not positive or above
  // the GL maximum (or tolerance::kMaxImageSidePx), Error(Gl) when there is
  // no current context or the framebuffer cannot be allocated, and for a GL
  // error the application left pending.
  void begin(int width, int height, Color background, Blending blending = Blending::Srgb);
  // The framebuffer as straight-alpha RGBA (sRGB encoded), row 0 at the top;
  // a new image the caller owns. Leaves the GL state as it was. Throws
  // Error(InvalidArgument) without begin(), Error(Gl) when reading fails.
  Image read_pixels() const;
  int width() const;
  int height() const;
  Blending blending() const;

 private:
  struct CURVETEXT_HIDDEN Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
