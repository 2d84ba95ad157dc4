// screen_blur's chain on the device: the shadow-factor query, the two blur
// passes and the composite, each drawn into a screen-sized target of its own.
#pragma once

#include "context.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::run_screen_blur.
Result<ScreenBlurOutput> run_screen_blur(Context& context, const ScreenBlurPrograms& programs,
                                         const ShadowMapImages& map, const FloatImage& receivers,
                                         const FloatImage& scene_colour, const ParamBlock& params);

}  // namespace penumbra::detail
