#include "vk/descriptor_set.hpp"

namespace penumbra::vk {

void write_uniform_buffer(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                          VkBuffer buffer, VkDeviceSize range) {
  const VkDescriptorBufferInfo info{buffer, 0, range};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void write_sampled_image(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                         VkImageView view, VkImageLayout layout, VkSampler sampler) {
  const VkDescriptorImageInfo info{sampler, view, layout};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

}  // namespace penumbra::vk
