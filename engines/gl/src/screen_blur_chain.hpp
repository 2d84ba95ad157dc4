// screen_blur's chain on the current context (docs/shader-interface.md,
// "The screen_blur chain"): the shadow-factor query, the two blur passes and
// the composite, each drawn into a screen-sized target of its own, as the
// Vulkan runtime's chain does.
#pragma once

#include "penumbra/gl/engine.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

struct ScreenBlurInputs {
  const FloatImage& normalized_depth;
  const FloatImage& receivers;
  const FloatImage& scene_colour;
  const ParamBlock& params;
};

// See GlEngine::run_screen_blur. Every object it creates is deleted before
// it returns.
Result<GlScreenBlurOutput> run_screen_blur_chain(const GlScreenBlurPasses& passes,
                                                 const ScreenBlurInputs& inputs);

}  // namespace penumbra::gl
