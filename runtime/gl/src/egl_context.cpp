#include "egl_context.hpp"

#include <EGL/eglext.h>

#include <utility>

#include "egl_error.hpp"

namespace penumbra::gl {
namespace {

// Attribute/value pairs, one pair per line.
// clang-format off
constexpr EGLint kContextAttributes[] = {
    EGL_CONTEXT_MAJOR_VERSION, 4,
    EGL_CONTEXT_MINOR_VERSION, 5,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
    EGL_NONE};
// clang-format on

// A config for a pbuffer-backed desktop GL context (the fallback when the
// display cannot make a context current without a surface).
Result<EGLConfig> choose_pbuffer_config(EGLDisplay display) {
  constexpr EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (eglChooseConfig(display, attributes, &config, 1, &count) != EGL_TRUE) {
    return egl_failure("eglChooseConfig", "choosing a pbuffer config for desktop OpenGL");
  }
  if (count == 0) {
    return make_error(Error::Kind::device, "eglChooseConfig",
                      "the display has no config with EGL_PBUFFER_BIT and EGL_OPENGL_BIT");
  }
  return config;
}

// Binds `api` for the calling thread while alive, then restores the previous
// API: EGL keeps one bound API per thread, which may be the application's.
class ApiBinding {
 public:
  explicit ApiBinding(EGLenum api) : previous_(eglQueryAPI()) { eglBindAPI(api); }
  ApiBinding(const ApiBinding&) = delete;
  ApiBinding& operator=(const ApiBinding&) = delete;
  ~ApiBinding() {
    if (previous_ != EGL_NONE) eglBindAPI(previous_);
  }

 private:
  EGLenum previous_;
};

}  // namespace

Result<EglContext> EglContext::create(DisplayUse display) {
  const EGLDisplay egl = display.get();
  const ApiBinding opengl(EGL_OPENGL_API);  // eglCreateContext reads the thread's API
  const bool surfaceless = display.has_extension("EGL_KHR_surfaceless_context") &&
                           display.has_extension("EGL_KHR_no_config_context");
  EGLConfig config = EGL_NO_CONFIG_KHR;
  EGLSurface surface = EGL_NO_SURFACE;
  if (!surfaceless) {
    auto chosen = choose_pbuffer_config(egl);
    if (!chosen) return chosen.error();
    config = *chosen;
    constexpr EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(egl, config, size);
    if (surface == EGL_NO_SURFACE) return egl_failure("eglCreatePbufferSurface", "a 1x1 pbuffer");
  }
  const EGLContext context = eglCreateContext(egl, config, EGL_NO_CONTEXT, kContextAttributes);
  if (context == EGL_NO_CONTEXT) {
    Error failure = egl_failure("eglCreateContext", "creating an OpenGL 4.5 core context");
    failure.message +=
        " (the driver offers no desktop OpenGL 4.5 core profile; Mesa's llvmpipe does)";
    if (surface != EGL_NO_SURFACE) eglDestroySurface(egl, surface);
    return failure;
  }
  return EglContext(std::move(display), context, surface);
}

EglContext::EglContext(DisplayUse display, EGLContext context, EGLSurface surface)
    : display_(std::move(display)), context_(context), surface_(surface) {}

EglContext::EglContext(EglContext&& other) noexcept
    : display_(std::move(other.display_)),
      context_(std::exchange(other.context_, EGL_NO_CONTEXT)),
      surface_(std::exchange(other.surface_, EGL_NO_SURFACE)) {}

EglContext::~EglContext() {
  // Destroying the context frees every GL object in it (nothing is shared).
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_.get(), context_);
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_.get(), surface_);
}

Result<CurrentScope> EglContext::make_current() const {
  // One context per client API may be current: save and replace the OpenGL API's.
  const ApiBinding opengl(EGL_OPENGL_API);
  CurrentScope scope;
  scope.display_ = eglGetCurrentDisplay();
  scope.context_ = eglGetCurrentContext();
  scope.draw_ = eglGetCurrentSurface(EGL_DRAW);
  scope.read_ = eglGetCurrentSurface(EGL_READ);
  if (eglMakeCurrent(display_.get(), surface_, surface_, context_) != EGL_TRUE) {
    return egl_failure("eglMakeCurrent", "making the OpenGL context current");
  }
  scope.own_display_ = display_.get();
  scope.active_ = true;
  return scope;
}

CurrentScope::CurrentScope(CurrentScope&& other) noexcept
    : active_(std::exchange(other.active_, false)),
      own_display_(other.own_display_),
      display_(other.display_),
      context_(other.context_),
      draw_(other.draw_),
      read_(other.read_) {}

CurrentScope::~CurrentScope() {
  if (!active_) return;
  const ApiBinding opengl(EGL_OPENGL_API);
  if (context_ == EGL_NO_CONTEXT) {
    eglMakeCurrent(own_display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  } else {
    eglMakeCurrent(display_, draw_, read_, context_);
  }
}

}  // namespace penumbra::gl
