// Building a shadow map's min-max mip on the device with a library's
// minmax_init and minmax_reduce passes, and reading it back.
#pragma once

#include <vector>

#include "context.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::build_minmax. Replaces any mip `map` had.
Result<MinmaxBuild> build_minmax(Context& context, ShadowMapImages& map, const PassProgram& init,
                                 const PassProgram& reduce, const ParamBlock& params);

// See Engine::read_minmax.
Result<std::vector<FloatImage>> read_minmax(Context& context, const ShadowMapImages& map);

}  // namespace penumbra::detail
