// The query pass on the current context, after the min-max mip when the
// query reads it, and the deferred pass, which reads a camera's depth in
// the receivers' place: from GLSL text and images to the pass's target.
#pragma once

#include <optional>

#include "gl_names.hpp"
#include "pass_inputs.hpp"
#include "pass_program.hpp"
#include "penumbra/gl/engine.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

struct QueryInputs {
  const FloatImage& normalized_depth;  // checked by check_shadow_map
  const FloatImage& receivers;         // checked by check_receivers
  const ParamBlock& params;
  DepthFormat map_format = DepthFormat::d32_float;  // the map's depth texture
};

// The query's images: the map as shadow_depth and shadow_cmp, the receivers.
void give_query_images(PassInputs& inputs, const QueryInputs& images);

// Builds the mip with `minmax` when the prepared `query` reads
// shadow_minmax, then draws the query into a new target of the receivers'
// size, which it returns. Errors: bad_input when the query's target has
// fewer than the two channels it writes (visibility, texel reads), or it
// reads shadow_minmax and `minmax` is empty; those of build_minmax_mip and
// draw_full_screen.
Result<Texture> draw_query(const PassProgram& query, const std::optional<GlMinmaxPasses>& minmax,
                           PassInputs& inputs, const QueryInputs& images);

// See GlEngine::run_query. Every object it creates is deleted before it
// returns.
Result<GlQueryOutput> run_query_pass(const GlQueryPasses& passes, const QueryInputs& images);

// See GlEngine::run_deferred. Every object it creates is deleted before it
// returns.
Result<GlQueryOutput> run_deferred_pass(const GlPass& pass, const FloatImage& normalized_depth,
                                        const FloatImage& camera_depth, const ParamBlock& params,
                                        DepthFormat map_format,
                                        const std::optional<GlMinmaxPasses>& minmax);

}  // namespace penumbra::gl
