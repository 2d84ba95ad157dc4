// DescriptorSetLayout: the bindings of one descriptor set.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using DescriptorSetLayout = DeviceObject<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;

// `set` only names the set in error messages.
Result<DescriptorSetLayout> create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings, std::uint32_t set);

}  // namespace penumbra::vk
