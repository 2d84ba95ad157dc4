// Turning EGL failures into penumbra::Error values.
#pragma once

#include <EGL/egl.h>

#include <string>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// The error's name and code, e.g. "EGL_BAD_MATCH (0x3009)".
std::string egl_error_name(EGLint error);

// Error{device, call, "<what> failed: <eglGetError() name>"}: call right
// after the failing EGL call, before any other EGL call resets the error.
Error egl_failure(std::string_view call, std::string_view what);

// Whether the space-separated extension list `extensions` (may be null)
// holds `name` as a whole word.
bool has_extension(const char* extensions, std::string_view name);

// Whether the EGL library offers the client extension `name`
// (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)).
bool has_client_extension(std::string_view name);

}  // namespace penumbra::gl
