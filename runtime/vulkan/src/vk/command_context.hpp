// CommandContext: records one-shot command buffers, submits them to the
// device's queue and waits on a fence, so every submission is finished (and
// its resources free to go) when submit() returns.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <string_view>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

class CommandContext {
 public:
  using Recorder = std::function<void(VkCommandBuffer)>;

  static Result<CommandContext> create(const Device& device);

  // Records `record`, submits and waits. `what` names the work in errors.
  Status submit(const Recorder& record, std::string_view what);

 private:
  CommandContext(const Device& device, DeviceObject<VkCommandPool, vkDestroyCommandPool> pool,
                 VkCommandBuffer commands, DeviceObject<VkFence, vkDestroyFence> fence);

  VkDevice device_;
  VkQueue queue_;
  DeviceObject<VkCommandPool, vkDestroyCommandPool> pool_;
  VkCommandBuffer commands_;  // freed with the pool
  DeviceObject<VkFence, vkDestroyFence> fence_;
};

}  // namespace penumbra::vk
