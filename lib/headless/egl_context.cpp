// Headless GL context through EGL, of the kind asked for (headless.hpp).
// Displays, in order of attempts:
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

#include <cstdio>
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

// What create() asks EGL for, per kind.
struct KindRequest {
  ContextKind kind;
  EGLenum api;            // eglBindAPI
  EGLint renderable_bit;  // EGL_RENDERABLE_TYPE of the config
  EGLint profile;         // EGL_CONTEXT_OPENGL_PROFILE_MASK; 0 for GLES
  int major, minor;
  std::string name;  // "OpenGL 3.3 core", for messages
};

bool is_desktop(ContextKind kind) { return kind == ContextKind::GlCore || kind == ContextKind::GlCompat; }

KindRequest request_for(const ContextOptions& options) {
  constexpr EGLint kEs3Bit = 0x0040;  // EGL_OPENGL_ES3_BIT (EGL 1.5, EGL_KHR_create_context)
  KindRequest r{options.kind, EGL_OPENGL_ES_API, EGL_OPENGL_ES2_BIT, 0, 2, 0, {}};
  switch (options.kind) {
    case ContextKind::Gles2:
      break;
    case ContextKind::Gles3:
      r.renderable_bit = kEs3Bit;
      r.major = 3;
      break;
    case ContextKind::GlCore:
    case ContextKind::GlCompat:
      r.api = EGL_OPENGL_API;
      r.renderable_bit = EGL_OPENGL_BIT;
      r.profile = options.kind == ContextKind::GlCore ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                      : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
      r.major = 3;
      r.minor = 3;
      break;
  }
  if (options.major != 0 || options.minor != 0) {
    const bool valid = options.minor >= 0 &&
                       (is_desktop(options.kind) ? options.major > 3 || (options.major == 3 && options.minor >= 2)
                                                 : options.major == r.major);
    if (!valid)
      throw Error(ErrorCode::InvalidArgument, std::string("a ") + context_kind_name(options.kind) +
                                                  " context cannot have version " + std::to_string(options.major) +
                                                  "." + std::to_string(options.minor));
    r.major = options.major;
    r.minor = options.minor;
  }
  r.name = std::string(is_desktop(options.kind) ? "OpenGL " : "OpenGL ES ") + std::to_string(r.major) + "." +
           std::to_string(r.minor) +
           (options.kind == ContextKind::GlCore     ? " core"
            : options.kind == ContextKind::GlCompat ? " compatibility"
                                                    : "");
  return r;
}

[[noreturn]] void fail_kind(const KindRequest& request, const std::string& message) {
  throw Error(ErrorCode::NoDevice, "no " + request.name + " context: " + message);
}

// EGL 1.5 and EGL_KHR_create_context take a minor version and a profile.
bool can_pick_version(EGLDisplay display) {
  int major = 0, minor = 0;
  const char* version = eglQueryString(display, EGL_VERSION);
  if (version != nullptr && std::sscanf(version, "%d.%d", &major, &minor) == 2 && (major > 1 || minor >= 5))
    return true;
  return has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_create_context");
}

EGLConfig choose_config(EGLDisplay display, const KindRequest& request, bool surfaceless) {
  const EGLint attribs[] = {EGL_RENDERABLE_TYPE,
                            request.renderable_bit,
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
  EGLint count = 0;
  if (eglChooseConfig(display, attribs, &config, 1, &count) != EGL_TRUE || count < 1)
    fail_kind(request, "the EGL display has no config for it (" + last_egl_error() + ")");
  return config;
}

EGLContext create_context(EGLDisplay display, EGLConfig config, const KindRequest& request) {
  std::vector<EGLint> attribs;
  if (can_pick_version(display)) {
    attribs = {EGL_CONTEXT_MAJOR_VERSION, request.major, EGL_CONTEXT_MINOR_VERSION, request.minor};
    if (request.profile != 0) attribs.insert(attribs.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, request.profile});
  } else if (request.api == EGL_OPENGL_ES_API) {
    attribs = {EGL_CONTEXT_CLIENT_VERSION, request.major};  // EGL 1.4: the major version only
  }  // EGL 1.4 desktop: whatever the driver gives, checked after.
  attribs.push_back(EGL_NONE);
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs.data());
  if (context == EGL_NO_CONTEXT) fail_kind(request, "eglCreateContext failed (" + last_egl_error() + ")");
  return context;
}

// GL_VERSION of the current context: "OpenGL ES 3.2 Mesa ..." or "4.5 (Core Profile) Mesa ...".
bool current_version(bool gles, int& major, int& minor) {
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (v == nullptr) return false;
  const char* prefix = "OpenGL ES ";
  const bool is_gles = std::strncmp(v, prefix, std::strlen(prefix)) == 0;
  if (is_gles != gles) return false;
  return std::sscanf(is_gles ? v + std::strlen(prefix) : v, "%d.%d", &major, &minor) == 2;
}

// The driver may give a later version than asked for, never an earlier one or
// another profile; EGL 1.4 cannot ask, so the check is what guarantees it.
void check_current(const KindRequest& request) {
  int major = 0, minor = 0;
  const bool gles = request.api == EGL_OPENGL_ES_API;
  const char* got = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const std::string got_text = got ? got : "no GL_VERSION";
  if (!current_version(gles, major, minor) || major < request.major ||
      (major == request.major && minor < request.minor))
    fail_kind(request, "the driver gave " + got_text);
  if (request.profile == 0) return;
  constexpr GLenum kContextProfileMask = 0x9126;  // GL_CONTEXT_PROFILE_MASK (desktop GL 3.2)
  GLint mask = 0;
  glGetIntegerv(kContextProfileMask, &mask);
  if ((mask & request.profile) == 0) fail_kind(request, "the driver gave another profile (" + got_text + ")");
}

}  // namespace

const char* context_kind_name(ContextKind kind) {
  switch (kind) {
    case ContextKind::Gles2:
      return "GLES 2";
    case ContextKind::Gles3:
      return "GLES 3";
    case ContextKind::GlCore:
      return "GL core";
    case ContextKind::GlCompat:
      return "GL compatibility";
  }
  return "unknown";
}

struct HeadlessContext::Impl {
  ContextKind kind = ContextKind::Gles2;
  EGLenum api = EGL_OPENGL_ES_API;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer only without surfaceless contexts

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (display == EGL_NO_DISPLAY) return;
    // Current contexts are per client API: release ours only, and leave the
    // thread's bound API as it was.
    const EGLenum previous_api = eglQueryAPI();
    eglBindAPI(api);
    if (eglGetCurrentContext() == context) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (previous_api != EGL_NONE) eglBindAPI(previous_api);
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    // eglTerminate is deliberately not called: displays are shared per
    // process, and terminating one would pull the rug from under another
    // HeadlessContext (or the caller's own EGL use) on the same display.
  }
};

HeadlessContext HeadlessContext::create(ContextKind kind) { return create(ContextOptions{kind, 0, 0}); }

HeadlessContext HeadlessContext::create(const ContextOptions& options) {
  const KindRequest request = request_for(options);
  auto impl = std::make_unique<Impl>();
  impl->kind = request.kind;
  impl->api = request.api;
  std::string why;
  impl->display = open_display(why);
  if (impl->display == EGL_NO_DISPLAY) {
    if (!why.empty()) why.resize(why.size() - 2);  // drop the trailing "; "
    fail(why);
  }
  if (eglBindAPI(request.api) != EGL_TRUE) fail_kind(request, "eglBindAPI failed (" + last_egl_error() + ")");

  const bool surfaceless = has_extension(eglQueryString(impl->display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
  const EGLConfig config = choose_config(impl->display, request, surfaceless);
  impl->context = create_context(impl->display, config, request);
  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    impl->surface = eglCreatePbufferSurface(impl->display, config, pbuffer_attribs);
    if (impl->surface == EGL_NO_SURFACE) fail_kind(request, "pbuffer creation failed (" + last_egl_error() + ")");
  }
  if (eglMakeCurrent(impl->display, impl->surface, impl->surface, impl->context) != EGL_TRUE)
    fail_kind(request, "eglMakeCurrent failed (" + last_egl_error() + ")");
  check_current(request);
  return HeadlessContext(std::move(impl));
}

HeadlessContext::HeadlessContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HeadlessContext::HeadlessContext(HeadlessContext&&) noexcept = default;
HeadlessContext& HeadlessContext::operator=(HeadlessContext&&) noexcept = default;
HeadlessContext::~HeadlessContext() = default;

void HeadlessContext::make_current() {
  if (!impl_) throw Error(ErrorCode::NoDevice, "no EGL display: context was moved from");
  if (eglBindAPI(impl_->api) != EGL_TRUE ||
      eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context) != EGL_TRUE) {
    throw Error(ErrorCode::NoDevice, "no EGL display: eglMakeCurrent failed (" + last_egl_error() + ")");
  }
}

ContextKind HeadlessContext::kind() const {
  if (!impl_) throw Error(ErrorCode::NoDevice, "no EGL display: context was moved from");
  return impl_->kind;
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
