// The query pass: a full-screen program reading receivers and the shadow map
// (and its min-max mip, when built).
#pragma once

#include "context.hpp"
#include "penumbra/runtime/engine.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::run_query_output.
Result<QueryOutput> run_query(Context& context, const PassProgram& program,
                              const ShadowMapImages& map, const FloatImage& receivers,
                              const ParamBlock& params);

}  // namespace penumbra::detail
