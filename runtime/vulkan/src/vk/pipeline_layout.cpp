#include "vk/pipeline_layout.hpp"

#include <cstdint>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<PipelineLayout> create_pipeline_layout(VkDevice device,
                                              std::span<const VkDescriptorSetLayout> sets) {
  VkPipelineLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  info.setLayoutCount = static_cast<std::uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreatePipelineLayout(device, &info, nullptr, &layout),
                     "vkCreatePipelineLayout", "creating a pipeline layout"));
  return PipelineLayout(device, layout);
}

}  // namespace penumbra::vk
