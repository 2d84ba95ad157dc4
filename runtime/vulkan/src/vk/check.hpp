// Turning VkResult codes into penumbra::Error values.
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::vk {

// The enumerator's name, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY".
const char* result_name(VkResult result);

// The enumerator's name for the formats the runtime uses, e.g. "VK_FORMAT_D32_SFLOAT".
const char* format_name(VkFormat format);

// Success, or Error{device, call, "<what> failed: <result name>"}.
Status check(VkResult result, const char* call, std::string_view what);

}  // namespace penumbra::vk
