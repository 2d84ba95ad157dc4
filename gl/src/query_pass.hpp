// One query pass on the current context, after the min-max mip when the
// query reads it: from GLSL text and images to the query's output.
#pragma once

#include "penumbra/gl/engine.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"
#include "sampler_objects.hpp"

namespace penumbra::gl {

struct QueryInputs {
  const GlQueryPasses& passes;
  const FloatImage& normalized_depth;
  const FloatImage& receivers;
  const ParamBlock& params;
};

// See GlEngine::run_query. Every object it creates is deleted before it
// returns.
Result<GlQueryOutput> run_query_pass(const SamplerObjects& samplers, const QueryInputs& inputs);

}  // namespace penumbra::gl
