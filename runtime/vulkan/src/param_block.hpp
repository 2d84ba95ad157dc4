// Packing a ParamBlock into the bytes of a uniform buffer, as the pass's
// reflection lays the ShadowParams members out in it.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "penumbra/support/result.hpp"
#include "penumbra/vulkan/program.hpp"
#include "reflection_binding.hpp"

namespace penumbra::detail {

// `buffer.size` bytes, each constant at its offset holding the first size/4
// floats of the ParamBlock entry named by its parameter (all four for the
// ShadowParams' vec4 members), and the half-pixel constant zero; bytes no
// constant covers are zero. A parameter the ParamBlock lacks, or a constant
// that is not 1 to 4 floats inside the buffer, is a bad_input Error (where =
// `pass`) naming it.
Result<std::vector<std::byte>> pack_params(const PlannedBinding& buffer, const ParamBlock& params,
                                           std::string_view pass);

}  // namespace penumbra::detail
