// One query pass on the current context: from GLSL text and images to the
// visibility image.
#pragma once

#include <string_view>

#include "param_binding.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"
#include "sampler_objects.hpp"

namespace penumbra::gl {

struct QueryInputs {
  std::string_view vertex_text;
  std::string_view fragment_text;
  const FloatImage& normalized_depth;
  const FloatImage& receivers;
  const ParamBlock& params;
};

// Builds the program, binds everything by name, draws the full-screen
// triangle into an R32F target of the receivers' size and reads it back.
// Every object it creates is deleted before it returns.
Result<FloatImage> run_query_pass(const SamplerObjects& samplers, const QueryInputs& inputs);

}  // namespace penumbra::gl
