// DeviceMemory: one allocation, of the first memory type that fits.
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using DeviceMemory = DeviceObject<VkDeviceMemory, vkFreeMemory>;

// Allocates memory for `requirements` with all of `properties`; `what` names
// the resource in error messages.
Result<DeviceMemory> allocate_memory(const Device& device, const VkMemoryRequirements& requirements,
                                     VkMemoryPropertyFlags properties, std::string_view what);

}  // namespace penumbra::vk
