#include "vk/buffer.hpp"

#include <string>
#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<Buffer> Buffer::create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                              std::string_view what) {
  const std::string name(what);
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer raw = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateBuffer(device.get(), &info, nullptr, &raw), "vkCreateBuffer",
                     "creating " + name + " (" + std::to_string(size) + " bytes)"));
  DeviceObject<VkBuffer, vkDestroyBuffer> buffer(device.get(), raw);

  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device.get(), raw, &requirements);
  // Coherent memory: host writes before a submission and reads after its fence need no flushes.
  auto memory = allocate_memory(
      device, requirements,
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, name);
  if (!memory) return memory.error();
  PENUMBRA_TRY(check(vkBindBufferMemory(device.get(), raw, memory->get(), 0), "vkBindBufferMemory",
                     "binding memory to " + name));
  void* mapped = nullptr;
  PENUMBRA_TRY(check(vkMapMemory(device.get(), memory->get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                     "vkMapMemory", "mapping " + name));
  return Buffer(std::move(*memory), std::move(buffer), size, static_cast<std::byte*>(mapped));
}

Buffer::Buffer(DeviceMemory memory, DeviceObject<VkBuffer, vkDestroyBuffer> buffer,
               VkDeviceSize size, std::byte* mapped)
    : memory_(std::move(memory)), buffer_(std::move(buffer)), size_(size), mapped_(mapped) {}

}  // namespace penumbra::vk
