// A headless EGL context for the GL proofs: desktop OpenGL 4.5 core (which
// compiles GLSL 3.30 and 4.50) or OpenGL ES 3.0, on Mesa's surfaceless
// display when EGL has it (else the default display), without a surface
// where the display allows it and with a 1x1 pbuffer otherwise. penumbra::gl
// keeps its context code private and makes desktop contexts only, hence
// this small one.
#pragma once

#include <EGL/egl.h>

#include <memory>

#include "penumbra/support/result.hpp"

namespace penumbra::testing {

enum class GlApi { desktop, es };

class EglContext {
 public:
  // The process's one context for `api`, created on first use, current on
  // this thread on return (the other API's is released) and kept until the
  // process exits; the error says why there is none.
  static Result<EglContext*> current(GlApi api);

  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

 private:
  EglContext(EGLDisplay display, EGLContext context, EGLSurface surface)
      : display_(display), context_(context), surface_(surface) {}

  EGLDisplay display_;
  EGLContext context_;
  EGLSurface surface_;
};

}  // namespace penumbra::testing
