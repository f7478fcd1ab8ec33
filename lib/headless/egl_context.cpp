// Headless GLES2 context through EGL. Order of attempts:
//   1. Mesa's surfaceless platform (no window system, no device node needed:
//      this is what gives llvmpipe on a machine without a GPU);
//   2. the device platform (EGL_EXT_platform_device; how NVIDIA's driver
//      offers headless contexts);
//   3. the default display (whatever the EGL implementation picks).
// Every failure becomes Error(NoDevice) with the EGL error name, never a crash,
// so callers (the CLI, tests) can report "no GL device" cleanly.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"

namespace curvetext {
namespace {

const char* egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default:
      return "unknown EGL error";
  }
}

std::string last_egl_error() { return egl_error_name(eglGetError()); }

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    const bool starts = (p == list || p[-1] == ' ');
    const bool ends = (p[n] == '\0' || p[n] == ' ');
    if (starts && ends) return true;
  }
  return false;
}

// Tries one display; on success it stays initialised and is returned.
EGLDisplay try_initialize(EGLDisplay display, std::string& why, const char* what) {
  if (display == EGL_NO_DISPLAY) {
    why += std::string(what) + ": no display (" + last_egl_error() + "); ";
    return EGL_NO_DISPLAY;
  }
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
    why += std::string(what) + ": eglInitialize failed (" + last_egl_error() + "); ";
    return EGL_NO_DISPLAY;
  }
  return display;
}

EGLDisplay open_display(std::string& why) {
  // Client extensions (EGL 1.5 / EGL_EXT_client_extensions): queried with no display.
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (client == nullptr) eglGetError();  // clear EGL_BAD_DISPLAY from old implementations
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));

  if (get_platform_display != nullptr && has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = try_initialize(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                                  why, "surfaceless platform");
    if (d != EGL_NO_DISPLAY) return d;
  }

  if (get_platform_display != nullptr && has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint count = 0;
    if (query_devices != nullptr && query_devices(0, nullptr, &count) == EGL_TRUE && count > 0) {
      std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
      if (query_devices(count, devices.data(), &count) == EGL_TRUE) {
        for (EGLint i = 0; i < count; ++i) {
          EGLDisplay d = try_initialize(
              get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr), why,
              "device platform");
          if (d != EGL_NO_DISPLAY) return d;
        }
      }
    } else {
      why += "device platform: no devices (" + last_egl_error() + "); ";
    }
  }

  return try_initialize(eglGetDisplay(EGL_DEFAULT_DISPLAY), why, "default display");
}

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::NoDevice, "no EGL display: " + message); }

}  // namespace

struct HeadlessContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer only without surfaceless contexts

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    // eglTerminate is deliberately not called: displays are shared per
    // process, and terminating one would pull the rug from under another
    // HeadlessContext (or the caller's own EGL use) on the same display.
  }
};

HeadlessContext HeadlessContext::create() {
  auto impl = std::make_unique<Impl>();
  std::string why;
  impl->display = open_display(why);
  if (impl->display == EGL_NO_DISPLAY) {
    if (!why.empty()) why.resize(why.size() - 2);  // drop the trailing "; "
    fail(why);
  }
  if (eglBindAPI(EGL_OPENGL_ES_API) != EGL_TRUE) fail("eglBindAPI(GLES) failed (" + last_egl_error() + ")");

  const char* display_ext = eglQueryString(impl->display, EGL_EXTENSIONS);
  const bool surfaceless = has_extension(display_ext, "EGL_KHR_surfaceless_context");

  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_ES2_BIT,
                                   EGL_SURFACE_TYPE,
                                   surfaceless ? 0 : EGL_PBUFFER_BIT,
                                   EGL_RED_SIZE,
                                   8,
                                   EGL_GREEN_SIZE,
                                   8,
                                   EGL_BLUE_SIZE,
                                   8,
                                   EGL_ALPHA_SIZE,
                                   8,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint num_configs = 0;
  if (eglChooseConfig(impl->display, config_attribs, &config, 1, &num_configs) != EGL_TRUE || num_configs < 1) {
    fail("no GLES2 config (" + last_egl_error() + ")");
  }

  const EGLint context_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  impl->context = eglCreateContext(impl->display, config, EGL_NO_CONTEXT, context_attribs);
  if (impl->context == EGL_NO_CONTEXT) fail("GLES2 context creation failed (" + last_egl_error() + ")");

  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    impl->surface = eglCreatePbufferSurface(impl->display, config, pbuffer_attribs);
    if (impl->surface == EGL_NO_SURFACE) fail("pbuffer creation failed (" + last_egl_error() + ")");
  }
  if (eglMakeCurrent(impl->display, impl->surface, impl->surface, impl->context) != EGL_TRUE) {
    fail("eglMakeCurrent failed (" + last_egl_error() + ")");
  }
  return HeadlessContext(std::move(impl));
}

HeadlessContext::HeadlessContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HeadlessContext::HeadlessContext(HeadlessContext&&) noexcept = default;
HeadlessContext& HeadlessContext::operator=(HeadlessContext&&) noexcept = default;
HeadlessContext::~HeadlessContext() = default;

void HeadlessContext::make_current() {
  if (!impl_) throw Error(ErrorCode::NoDevice, "no EGL display: context was moved from");
  if (eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context) != EGL_TRUE) {
    throw Error(ErrorCode::NoDevice, "no EGL display: eglMakeCurrent failed (" + last_egl_error() + ")");
  }
}

namespace {
std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
}
}  // namespace

std::string HeadlessContext::renderer() const { return gl_string(GL_RENDERER); }
std::string HeadlessContext::version() const { return gl_string(GL_VERSION); }

}  // namespace curvetext
