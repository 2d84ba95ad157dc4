// EglContext: a desktop OpenGL 4.5 core context on an EGL display, with no
// surface where the display allows it (EGL_KHR_surfaceless_context) and a
// 1x1 pbuffer otherwise. Rendering goes to framebuffer objects either way.
// CurrentScope makes it current on the calling thread for one call.
#pragma once

#include <EGL/egl.h>

#include "egl_display.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// While alive, the context is current on this thread for the OpenGL API; on
// destruction, whatever OpenGL context was current before (or none) is current
// again and the thread's bound EGL API is restored.
class CurrentScope {
 public:
  CurrentScope(CurrentScope&& other) noexcept;
  CurrentScope& operator=(CurrentScope&&) = delete;
  CurrentScope(const CurrentScope&) = delete;
  ~CurrentScope();

 private:
  friend class EglContext;
  CurrentScope() = default;

  bool active_ = false;
  EGLDisplay own_display_ = EGL_NO_DISPLAY;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface draw_ = EGL_NO_SURFACE;
  EGLSurface read_ = EGL_NO_SURFACE;
};

class EglContext {
 public:
  // Errors (device): no config or no 4.5 core context on `display`.
  static Result<EglContext> create(DisplayUse display);

  EglContext(EglContext&& other) noexcept;
  EglContext& operator=(EglContext&&) = delete;
  EglContext(const EglContext&) = delete;
  ~EglContext();

  // Errors (device): eglMakeCurrent failed.
  Result<CurrentScope> make_current() const;

 private:
  EglContext(DisplayUse display, EGLContext context, EGLSurface surface);

  DisplayUse display_;  // declared first: released after the context
  EGLContext context_;
  EGLSurface surface_;
};

}  // namespace penumbra::gl
