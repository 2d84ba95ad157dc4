// Sampler objects made from the sampler state a reflection gives each
// texture (docs/shader-interface.md): filter, mip filter, comparison, and
// clamp-to-edge addressing.
#pragma once

#include "gl_names.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// A new sampler object in the current context for `state`: GL_NEAREST or
// GL_LINEAR; with mip_filter nearest, GL_NEAREST_MIPMAP_NEAREST (or
// GL_LINEAR_MIPMAP_NEAREST) minification with the LOD range from 0 up, so
// an integer LOD reads that level; comparison as GL_COMPARE_REF_TO_TEXTURE
// with GL_LEQUAL; GL_CLAMP_TO_EDGE. Errors (device): a GL error.
Result<Sampler> create_sampler_object(const SamplerState& state);

}  // namespace penumbra::gl
