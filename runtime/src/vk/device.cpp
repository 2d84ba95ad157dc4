#include "vk/device.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

std::optional<std::uint32_t> graphics_family(VkPhysicalDevice physical) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueCount > 0 && (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) return i;
  }
  return std::nullopt;
}

}  // namespace

Result<std::shared_ptr<const Device>> Device::create(std::shared_ptr<const Instance> instance,
                                                     VkPhysicalDevice physical) {
  std::shared_ptr<Device> device(new Device());
  device->instance_ = std::move(instance);
  device->physical_ = physical;
  vkGetPhysicalDeviceProperties(physical, &device->properties_);
  vkGetPhysicalDeviceMemoryProperties(physical, &device->memory_);

  const std::optional<std::uint32_t> family = graphics_family(physical);
  if (!family) {
    return make_error(Error::Kind::device, "vkGetPhysicalDeviceQueueFamilyProperties",
                      std::string(device->properties_.deviceName) + " has no graphics queue");
  }
  device->queue_family_ = *family;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = *family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  PENUMBRA_TRY(check(vkCreateDevice(physical, &info, nullptr, &device->device_), "vkCreateDevice",
                     std::string("opening ") + device->properties_.deviceName));
  vkGetDeviceQueue(device->device_, *family, 0, &device->queue_);
  return std::shared_ptr<const Device>(std::move(device));
}

std::uint32_t Device::api_version() const {
  return std::min(properties_.apiVersion, Instance::kApiVersion);
}

Device::~Device() {
  if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
}

}  // namespace penumbra::vk
