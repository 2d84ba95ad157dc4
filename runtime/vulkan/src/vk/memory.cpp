#include "vk/memory.hpp"

#include <optional>
#include <string>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

std::optional<std::uint32_t> memory_type(const VkPhysicalDeviceMemoryProperties& memory,
                                         std::uint32_t allowed_types,
                                         VkMemoryPropertyFlags properties) {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    const bool allowed = (allowed_types & (1u << i)) != 0;
    if (allowed && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
  }
  return std::nullopt;
}

}  // namespace

Result<DeviceMemory> allocate_memory(const Device& device, const VkMemoryRequirements& requirements,
                                     VkMemoryPropertyFlags properties, std::string_view what) {
  const std::optional<std::uint32_t> type =
      memory_type(device.memory_properties(), requirements.memoryTypeBits, properties);
  if (!type) {
    return make_error(Error::Kind::device, "vkAllocateMemory",
                      std::string("no memory type suits ") + std::string(what) +
                          " (needs memory property flags " + std::to_string(properties) + ")");
  }
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = *type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkAllocateMemory(device.get(), &info, nullptr, &memory), "vkAllocateMemory",
                     std::string("allocating memory for ") + std::string(what)));
  return DeviceMemory(device.get(), memory);
}

}  // namespace penumbra::vk
