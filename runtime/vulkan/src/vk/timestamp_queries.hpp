// TimestampQueries: a VkQueryPool of two timestamps bracketing the commands
// recorded between begin() and end() in one command buffer, read back as
// the GPU time between them.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

class TimestampQueries {
 public:
  // None (no error) when the device's queue writes no timestamps
  // (timestampValidBits 0) or reports no timestamp period.
  static Result<std::optional<TimestampQueries>> create(const Device& device);

  // Resets both queries and writes the first timestamp once every earlier
  // command has started; record outside a render pass.
  void begin(VkCommandBuffer commands) const;
  // Writes the second timestamp once every command before it has finished.
  void end(VkCommandBuffer commands) const;
  // Milliseconds between the two, after the command buffer has completed.
  Result<double> elapsed_ms() const;

 private:
  TimestampQueries(VkDevice device, DeviceObject<VkQueryPool, vkDestroyQueryPool> pool,
                   std::uint32_t valid_bits, float period_ns);

  VkDevice device_;
  DeviceObject<VkQueryPool, vkDestroyQueryPool> pool_;
  std::uint32_t valid_bits_;
  float period_ns_;  // nanoseconds per timestamp tick
};

}  // namespace penumbra::vk
