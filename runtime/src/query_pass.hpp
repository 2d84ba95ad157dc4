// The query pass: a full-screen program reading receivers and the shadow map.
#pragma once

#include "context.hpp"
#include "penumbra/support/image.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::run_query.
Result<FloatImage> run_query(Context& context, const PassProgram& program,
                             const ShadowMapImages& map, const FloatImage& receivers,
                             const ParamBlock& params);

}  // namespace penumbra::detail
