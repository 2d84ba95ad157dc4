// What the current OpenGL context reports about itself.
#pragma once

#include "penumbra/gl/engine.hpp"

namespace penumbra::gl {

// GL_RENDERER, GL_VERSION and GL_SHADING_LANGUAGE_VERSION of the context
// current on this thread.
GlInfo current_context_info();

}  // namespace penumbra::gl
