// Opening the OpenGL context GlEngineOptions::device asks for: the default
// display (Mesa's surfaceless platform, else EGL_DEFAULT_DISPLAY), or an EGL
// device by index or by a substring of its renderer.
#pragma once

#include <string>

#include "egl_context.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

struct OpenedContext {
  EglContext context;
  std::string display;  // how it was opened, for diagnostics
};

// Errors: device when EGL or the display is unusable, or when a selector is
// given but EGL cannot enumerate devices; bad_input when the selector matches
// no device (the message lists them as "index: renderer").
Result<OpenedContext> open_context(const std::string& selector);

}  // namespace penumbra::gl
