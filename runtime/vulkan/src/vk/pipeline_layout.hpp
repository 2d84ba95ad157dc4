// PipelineLayout: the descriptor set layouts of a pipeline, set 0 first.
#pragma once

#include <vulkan/vulkan.h>

#include <span>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using PipelineLayout = DeviceObject<VkPipelineLayout, vkDestroyPipelineLayout>;

Result<PipelineLayout> create_pipeline_layout(VkDevice device,
                                              std::span<const VkDescriptorSetLayout> sets);

}  // namespace penumbra::vk
