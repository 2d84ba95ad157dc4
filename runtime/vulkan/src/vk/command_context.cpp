#include "vk/command_context.hpp"

#include <cstdint>
#include <string>
#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<CommandContext> CommandContext::create(const Device& device) {
  VkCommandPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  // Lets vkBeginCommandBuffer reset the one buffer for every submission.
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = device.queue_family();
  VkCommandPool raw_pool = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateCommandPool(device.get(), &pool_info, nullptr, &raw_pool),
                     "vkCreateCommandPool", "creating the command pool"));
  DeviceObject<VkCommandPool, vkDestroyCommandPool> pool(device.get(), raw_pool);

  VkCommandBufferAllocateInfo buffer_info{};
  buffer_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  buffer_info.commandPool = raw_pool;
  buffer_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  buffer_info.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkAllocateCommandBuffers(device.get(), &buffer_info, &commands),
                     "vkAllocateCommandBuffers", "allocating the command buffer"));

  VkFenceCreateInfo fence_info{};
  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence raw_fence = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateFence(device.get(), &fence_info, nullptr, &raw_fence), "vkCreateFence",
                     "creating the submission fence"));
  return CommandContext(device, std::move(pool), commands,
                        DeviceObject<VkFence, vkDestroyFence>(device.get(), raw_fence));
}

CommandContext::CommandContext(const Device& device,
                               DeviceObject<VkCommandPool, vkDestroyCommandPool> pool,
                               VkCommandBuffer commands,
                               DeviceObject<VkFence, vkDestroyFence> fence)
    : device_(device.get()),
      queue_(device.queue()),
      pool_(std::move(pool)),
      commands_(commands),
      fence_(std::move(fence)) {}

Status CommandContext::submit(const Recorder& record, std::string_view what) {
  const std::string name(what);
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PENUMBRA_TRY(check(vkBeginCommandBuffer(commands_, &begin), "vkBeginCommandBuffer",
                     "starting to record " + name));
  record(commands_);
  PENUMBRA_TRY(check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer",
                     "finishing the recording of " + name));

  const VkFence fence = fence_.get();
  PENUMBRA_TRY(check(vkResetFences(device_, 1, &fence), "vkResetFences", "resetting the fence"));
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  PENUMBRA_TRY(
      check(vkQueueSubmit(queue_, 1, &submit, fence), "vkQueueSubmit", "submitting " + name));
  // No timeout: returning early would free resources the device still uses.
  return check(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences",
               "waiting for " + name);
}

}  // namespace penumbra::vk
