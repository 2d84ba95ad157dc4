// DisplayUse: one engine's share of an initialized EGL display. Engines on
// the same display (Mesa's surfaceless display is one per process) share its
// initialization; the display is terminated when the last of them goes, and
// never when it was already initialized before Penumbra first used it (the
// application owns it then).
#pragma once

#include <EGL/egl.h>

#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::gl {

class DisplayUse {
 public:
  // eglInitialize()s `display` unless engines already use it. `display` is
  // what `get_call` (eglGetPlatformDisplay or eglGetDisplay) returned:
  // EGL_NO_DISPLAY is its failure. `what` names the display in errors
  // ("Mesa's surfaceless display").
  static Result<DisplayUse> acquire(EGLDisplay display, std::string_view get_call,
                                    std::string_view what);

  DisplayUse(DisplayUse&& other) noexcept;
  DisplayUse& operator=(DisplayUse&&) = delete;
  DisplayUse(const DisplayUse&) = delete;
  ~DisplayUse();

  EGLDisplay get() const { return display_; }
  bool has_extension(std::string_view name) const;

 private:
  explicit DisplayUse(EGLDisplay display) : display_(display) {}

  EGLDisplay display_;
};

}  // namespace penumbra::gl
