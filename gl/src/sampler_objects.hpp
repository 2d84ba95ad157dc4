// The two sampler objects every query pass binds with the one depth texture
// (docs/shader-interface.md): `point` for shadow_depth and receivers
// (nearest, no comparison) and `compare` for shadow_cmp (linear, LEQUAL
// comparison); both clamp to the edge.
#pragma once

#include "gl_api.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Plain names, not owning wrappers: they live as long as the context, and
// destroying the context frees them.
struct SamplerObjects {
  GLuint point = 0;
  GLuint compare = 0;
};

// Creates both in the current context. Errors (device): a GL error.
Result<SamplerObjects> create_sampler_objects();

}  // namespace penumbra::gl
