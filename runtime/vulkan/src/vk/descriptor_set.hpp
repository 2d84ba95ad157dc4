// Descriptor set updates: pointing a set's bindings at a buffer or an image.
// Sets themselves come from a DescriptorPool and are freed with it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace penumbra::vk {

void write_uniform_buffer(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                          VkBuffer buffer, VkDeviceSize range);

// A combined image sampler; `layout` is the one the image is in when sampled.
void write_sampled_image(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                         VkImageView view, VkImageLayout layout, VkSampler sampler);

}  // namespace penumbra::vk
