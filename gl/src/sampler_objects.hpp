// The sampler objects every pass binds (docs/shader-interface.md): `point`
// for shadow_depth, receivers and minmax_source (nearest, no comparison),
// `compare` for shadow_cmp (linear, LEQUAL comparison) and `mip` for
// shadow_minmax (nearest texel of the nearest level, every level reachable);
// all clamp to the edge.
#pragma once

#include "gl_api.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Plain names, not owning wrappers: they live as long as the context, and
// destroying the context frees them.
struct SamplerObjects {
  GLuint point = 0;
  GLuint compare = 0;
  GLuint mip = 0;
};

// Creates all three in the current context. Errors (device): a GL error.
Result<SamplerObjects> create_sampler_objects();

}  // namespace penumbra::gl
