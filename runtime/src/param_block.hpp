// Packing a ParamBlock into the bytes of the ShadowParams uniform block.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "binding_plan.hpp"
#include "penumbra/runtime/program.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::detail {

// `layout.size` bytes, each member at its reflected offset holding the first
// size/4 floats of the ParamBlock entry of the same name (all four for the
// interface's vec4 members); bytes no member covers are zero. A member the
// ParamBlock lacks, or one that is not 1 to 4 floats, is a bad_input Error
// (where = `pass`) naming it.
Result<std::vector<std::byte>> pack_params(const ParamsLayout& layout, const ParamBlock& params,
                                           std::string_view pass);

}  // namespace penumbra::detail
