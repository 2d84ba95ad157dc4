// The query pass: a full-screen program reading receivers and the shadow map
// (and its min-max mip, when built); and the deferred pass, which reads a
// camera's depth in the receivers' place.
#pragma once

#include "context.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "shadow_map_images.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// `receivers` checked (channels, size) and uploaded as the RGBA32F receivers
// image, in SHADER_READ_ONLY_OPTIMAL.
Result<vk::Image> upload_receivers(Context& context, const FloatImage& receivers);

// See Engine::run_query_output.
Result<QueryOutput> run_query(Context& context, const PassProgram& program,
                              const ShadowMapImages& map, const FloatImage& receivers,
                              const ParamBlock& params);

// See Engine::run_deferred.
Result<QueryOutput> run_deferred(Context& context, const PassProgram& program,
                                 const ShadowMapImages& map, const FloatImage& camera_depth,
                                 const ParamBlock& params);

}  // namespace penumbra::detail
