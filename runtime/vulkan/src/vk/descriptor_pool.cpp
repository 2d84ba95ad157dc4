#include "vk/descriptor_pool.hpp"

#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<DescriptorPool> DescriptorPool::create(VkDevice device,
                                              std::span<const VkDescriptorPoolSize> sizes,
                                              std::uint32_t max_sets) {
  VkDescriptorPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  info.maxSets = max_sets;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateDescriptorPool(device, &info, nullptr, &pool),
                     "vkCreateDescriptorPool", "creating a descriptor pool"));
  return DescriptorPool(device,
                        DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool>(device, pool));
}

DescriptorPool::DescriptorPool(VkDevice device,
                               DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool> pool)
    : device_(device), pool_(std::move(pool)) {}

Result<VkDescriptorSet> DescriptorPool::allocate(VkDescriptorSetLayout layout) {
  VkDescriptorSetAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  info.descriptorPool = pool_.get();
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkAllocateDescriptorSets(device_, &info, &set), "vkAllocateDescriptorSets",
                     "allocating a descriptor set"));
  return set;
}

}  // namespace penumbra::vk
