// spirv-val with Vulkan 1.0 rules: the one validator wrapper for the
// pipeline's SPIR-V and for a front end's SPIR-V.
#pragma once

#include <cstdint>
#include <span>

#include "penumbra/support/result.hpp"

namespace penumbra {

// An Error (message only: the validator's messages, one a line) when the
// module is not valid Vulkan 1.0 SPIR-V.
Status validate_vulkan_spirv(std::span<const std::uint32_t> spirv);

}  // namespace penumbra
