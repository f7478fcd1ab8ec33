// A GLES2 context without a window (EGL surfaceless or device platform). On a
// machine without a GPU this is Mesa's llvmpipe. The context is current on the
// creating thread while the object lives.
#pragma once

#include <memory>
#include <string>

namespace curvetext {

class HeadlessContext {
 public:
  // Throws Error(NoDevice) with the reason (no EGL display, no GLES2 config,
  // context creation failed).
  static HeadlessContext create();

  HeadlessContext(HeadlessContext&&) noexcept;
  HeadlessContext& operator=(HeadlessContext&&) noexcept;
  ~HeadlessContext();

  void make_current();
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;   // GL_VERSION

  struct Impl;

 private:
  explicit HeadlessContext(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
