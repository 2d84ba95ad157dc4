// A shadow map's min-max mip gathered from the levels its passes drew, and
// read back.
#pragma once

#include <vector>

#include "context.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "shadow_map_images.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// The mip of a width x height map: `levels` (1..N, each at rest in
// SHADER_READ_ONLY_OPTIMAL) copied into the chain, its padding 1.0 (the far
// plane, as the map's clear), left in kMinmaxLayout.
Result<MinmaxMip> gather_minmax(Context& context, int width, int height,
                                const std::vector<const vk::Image*>& levels);

// See Engine::read_minmax.
Result<std::vector<FloatImage>> read_minmax(Context& context, const ShadowMapImages& map);

}  // namespace penumbra::detail
