// DescriptorPool: the pool one pass allocates its descriptor sets from; the
// sets are freed with it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

class DescriptorPool {
 public:
  // Room for `max_sets` sets holding `sizes` descriptors in all.
  static Result<DescriptorPool> create(VkDevice device, std::span<const VkDescriptorPoolSize> sizes,
                                       std::uint32_t max_sets);

  Result<VkDescriptorSet> allocate(VkDescriptorSetLayout layout);

 private:
  DescriptorPool(VkDevice device, DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool> pool);

  VkDevice device_;
  DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool> pool_;
};

}  // namespace penumbra::vk
