#include "vk/descriptor_set_layout.hpp"

#include <string>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<DescriptorSetLayout> create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings, std::uint32_t set) {
  VkDescriptorSetLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
                     "vkCreateDescriptorSetLayout",
                     "creating the layout of descriptor set " + std::to_string(set)));
  return DescriptorSetLayout(device, layout);
}

}  // namespace penumbra::vk
