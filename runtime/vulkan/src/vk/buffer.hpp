// Buffer: a VkBuffer in host-visible, coherent memory, mapped for its lifetime.
// The runtime uses buffers for staging, vertices and uniforms, all written or
// read by the host around a fenced submission.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string_view>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"
#include "vk/device_object.hpp"
#include "vk/memory.hpp"

namespace penumbra::vk {

class Buffer {
 public:
  // `what` names the buffer in error messages ("the vertex buffer").
  static Result<Buffer> create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                               std::string_view what);

  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  // The mapped contents.
  std::span<std::byte> bytes() const { return {mapped_, static_cast<std::size_t>(size_)}; }

 private:
  Buffer(DeviceMemory memory, DeviceObject<VkBuffer, vkDestroyBuffer> buffer, VkDeviceSize size,
         std::byte* mapped);

  DeviceMemory memory_;  // declared first: freed after the buffer is destroyed
  DeviceObject<VkBuffer, vkDestroyBuffer> buffer_;
  VkDeviceSize size_;
  std::byte* mapped_;  // freeing the memory unmaps it
};

}  // namespace penumbra::vk
