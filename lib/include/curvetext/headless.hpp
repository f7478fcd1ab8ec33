// A GL context without a window (EGL surfaceless or device platform). On a
// machine without a GPU this is Mesa's llvmpipe. create() makes the context
// current on the calling thread.
//
// Every kind is reached through the library's one GL link (libGLESv2 of
// libglvnd): glvnd dispatches each gl* call to the current context, desktop
// GL included, so a caller of a desktop kind calls the same functions.
// Functions that exist only in desktop GL are not exported there: get them
// with eglGetProcAddress.
#pragma once

#include <memory>
#include <string>

#include "curvetext/export.hpp"

namespace curvetext {

enum class ContextKind {
  // OpenGL ES 2.0 or a later version compatible with it: Mesa answers with
  // the highest ES it has (OpenGL ES 3.2 on llvmpipe) unless
  // MESA_GLES_VERSION_OVERRIDE=2.0 is set before the context is created.
  Gles2,
  Gles3,     // OpenGL ES 3.0 or later
  GlCore,    // desktop OpenGL 3.3 or later, core profile
  GlCompat,  // desktop OpenGL 3.3 or later, compatibility profile
};

// "GLES 2", "GLES 3", "GL core", "GL compatibility": a static string.
CURVETEXT_API const char* context_kind_name(ContextKind kind);

struct ContextOptions {
  ContextKind kind = ContextKind::Gles2;
  // The lowest version accepted; 0: the kind's (2.0, 3.0, 3.3, 3.3). GLES
  // kinds take their own major version only; desktop kinds 3.2 or later
  // (profiles begin there).
  int major = 0;
  int minor = 0;
};

// Owns the EGL context (and a 1x1 pbuffer where surfaceless contexts are
// missing); destroying it releases the context from the calling thread if
// current there. The EGL display is shared per process and left open. Not
// thread-safe: one thread at a time, and GL objects made in it (Renderer,
// DrawBatch, GlyphCache buffers) must go before it does. Distinct contexts
// may be used on distinct threads. A moved-from context may only be
// assigned to or destroyed.
class CURVETEXT_API HeadlessContext {
 public:
  // Throws Error(NoDevice) with the reason (no EGL display, no config or no
  // context of the kind asked for, or a context older than asked for), and
  // Error(InvalidArgument) for a version the kind cannot have.
  static HeadlessContext create(ContextKind kind = ContextKind::Gles2);
  static HeadlessContext create(const ContextOptions& options);

  HeadlessContext(HeadlessContext&&) noexcept;
  HeadlessContext& operator=(HeadlessContext&&) noexcept;
  ~HeadlessContext();

  // Makes the context current on the calling thread (it must not be current
  // on another one). Throws Error(NoDevice) when EGL refuses.
  void make_current();
  ContextKind kind() const;
  // Of the context current on the calling thread (make_current() first when
  // there are several); empty without one.
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;   // GL_VERSION, e.g. "OpenGL ES 3.2 Mesa 22.3.6", "4.5 (Core Profile) Mesa 22.3.6"

 private:
  struct CURVETEXT_HIDDEN Impl;
  explicit HeadlessContext(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
