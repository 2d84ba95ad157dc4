// Choosing the physical device EngineOptions::device names.
#pragma once

#include <vulkan/vulkan.h>

#include <span>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::detail {

// `selector`: "" prefers lavapipe ("llvmpipe" in the name), else the first
// device; all digits is an index; anything else is a case-insensitive
// substring of the device name, first match wins. When nothing matches, the
// Error lists every device as "index: name".
Result<VkPhysicalDevice> select_physical_device(std::span<const VkPhysicalDevice> devices,
                                                std::string_view selector);

}  // namespace penumbra::detail
