// Device: the logical VkDevice on one physical device, with its graphics queue.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>

#include "penumbra/support/result.hpp"
#include "vk/instance.hpp"

namespace penumbra::vk {

class Device {
 public:
  // Opens `physical` with one queue of its first graphics-capable family.
  // Holds `instance`, so the instance outlives every device made from it.
  static Result<std::shared_ptr<const Device>> create(std::shared_ptr<const Instance> instance,
                                                      VkPhysicalDevice physical);
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  ~Device();

  VkDevice get() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  // The queue family's timestampValidBits: 0 when its queue writes no timestamps.
  std::uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  // The version the runtime may use: the device's, capped by the instance's.
  std::uint32_t api_version() const;
  // VK_EXT_depth_clip_control is enabled: pipelines may clip z in [-w, w].
  bool depth_clip_control() const { return depth_clip_control_; }
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_; }

 private:
  Device() = default;

  std::shared_ptr<const Instance> instance_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  std::uint32_t timestamp_valid_bits_ = 0;
  VkPhysicalDeviceProperties properties_{};
  bool depth_clip_control_ = false;
  VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace penumbra::vk
