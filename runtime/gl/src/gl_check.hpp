// Turning glGetError() codes into penumbra::Error values.
#pragma once

#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Success when GL has recorded no error since the last check; otherwise
// Error{device, "OpenGL", "<what> failed: GL_OUT_OF_MEMORY (0x0505)"},
// naming every recorded error (all are cleared).
Status check_gl(std::string_view what);

}  // namespace penumbra::gl
