#include "vk/device.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

struct QueueFamily {
  std::uint32_t index = 0;
  std::uint32_t timestamp_valid_bits = 0;
};

std::optional<QueueFamily> graphics_family(VkPhysicalDevice physical) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueCount > 0 && (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
      return QueueFamily{i, families[i].timestampValidBits};
    }
  }
  return std::nullopt;
}

bool has_extension(VkPhysicalDevice physical, const char* name) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [name](const VkExtensionProperties& e) {
    return std::string_view(e.extensionName) == name;
  });
}

// GL clip space (z in [-w, w]) for GLSL text fixed up for OpenGL; optional.
bool supports_depth_clip_control(VkPhysicalDevice physical) {
  if (!has_extension(physical, VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME)) return false;
  VkPhysicalDeviceDepthClipControlFeaturesEXT clip{};
  clip.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &clip;
  vkGetPhysicalDeviceFeatures2(physical, &features);
  return clip.depthClipControl == VK_TRUE;
}

}  // namespace

Result<std::shared_ptr<const Device>> Device::create(std::shared_ptr<const Instance> instance,
                                                     VkPhysicalDevice physical) {
  std::shared_ptr<Device> device(new Device());
  device->instance_ = std::move(instance);
  device->physical_ = physical;
  vkGetPhysicalDeviceProperties(physical, &device->properties_);
  vkGetPhysicalDeviceMemoryProperties(physical, &device->memory_);

  const std::optional<QueueFamily> family = graphics_family(physical);
  if (!family) {
    return make_error(Error::Kind::device, "vkGetPhysicalDeviceQueueFamilyProperties",
                      std::string(device->properties_.deviceName) + " has no graphics queue");
  }
  device->queue_family_ = family->index;
  device->timestamp_valid_bits_ = family->timestamp_valid_bits;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = family->index;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  VkPhysicalDeviceDepthClipControlFeaturesEXT clip{};
  clip.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT;
  clip.depthClipControl = VK_TRUE;
  const char* clip_extension = VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME;
  if (device->properties_.apiVersion >= VK_API_VERSION_1_1 &&
      supports_depth_clip_control(physical)) {
    device->depth_clip_control_ = true;
    info.pNext = &clip;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &clip_extension;
  }
  PENUMBRA_TRY(check(vkCreateDevice(physical, &info, nullptr, &device->device_), "vkCreateDevice",
                     std::string("opening ") + device->properties_.deviceName));
  vkGetDeviceQueue(device->device_, family->index, 0, &device->queue_);
  return std::shared_ptr<const Device>(std::move(device));
}

std::uint32_t Device::api_version() const {
  return std::min(properties_.apiVersion, Instance::kApiVersion);
}

Device::~Device() {
  if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
}

}  // namespace penumbra::vk
