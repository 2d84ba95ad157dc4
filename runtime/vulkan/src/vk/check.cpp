#include "vk/check.hpp"

#include <string>
#include <utility>

namespace penumbra::vk {
namespace {

template <typename Enum, std::size_t N>
const char* lookup(const std::pair<Enum, const char*> (&names)[N], Enum value,
                   const char* fallback) {
  for (const auto& [known, name] : names) {
    if (known == value) return name;
  }
  return fallback;
}

constexpr std::pair<VkResult, const char*> kResultNames[] = {
    {VK_SUCCESS, "VK_SUCCESS"},
    {VK_NOT_READY, "VK_NOT_READY"},
    {VK_TIMEOUT, "VK_TIMEOUT"},
    {VK_INCOMPLETE, "VK_INCOMPLETE"},
    {VK_ERROR_OUT_OF_HOST_MEMORY, "VK_ERROR_OUT_OF_HOST_MEMORY"},
    {VK_ERROR_OUT_OF_DEVICE_MEMORY, "VK_ERROR_OUT_OF_DEVICE_MEMORY"},
    {VK_ERROR_INITIALIZATION_FAILED, "VK_ERROR_INITIALIZATION_FAILED"},
    {VK_ERROR_DEVICE_LOST, "VK_ERROR_DEVICE_LOST"},
    {VK_ERROR_MEMORY_MAP_FAILED, "VK_ERROR_MEMORY_MAP_FAILED"},
    {VK_ERROR_LAYER_NOT_PRESENT, "VK_ERROR_LAYER_NOT_PRESENT"},
    {VK_ERROR_EXTENSION_NOT_PRESENT, "VK_ERROR_EXTENSION_NOT_PRESENT"},
    {VK_ERROR_FEATURE_NOT_PRESENT, "VK_ERROR_FEATURE_NOT_PRESENT"},
    {VK_ERROR_INCOMPATIBLE_DRIVER, "VK_ERROR_INCOMPATIBLE_DRIVER"},
    {VK_ERROR_TOO_MANY_OBJECTS, "VK_ERROR_TOO_MANY_OBJECTS"},
    {VK_ERROR_FORMAT_NOT_SUPPORTED, "VK_ERROR_FORMAT_NOT_SUPPORTED"},
    {VK_ERROR_FRAGMENTED_POOL, "VK_ERROR_FRAGMENTED_POOL"},
    {VK_ERROR_UNKNOWN, "VK_ERROR_UNKNOWN"},
    {VK_ERROR_OUT_OF_POOL_MEMORY, "VK_ERROR_OUT_OF_POOL_MEMORY"},
};

constexpr std::pair<VkFormat, const char*> kFormatNames[] = {
    {VK_FORMAT_D32_SFLOAT, "VK_FORMAT_D32_SFLOAT"},
    {VK_FORMAT_X8_D24_UNORM_PACK32, "VK_FORMAT_X8_D24_UNORM_PACK32"},
    {VK_FORMAT_D16_UNORM, "VK_FORMAT_D16_UNORM"},
    {VK_FORMAT_R32_SFLOAT, "VK_FORMAT_R32_SFLOAT"},
    {VK_FORMAT_R32G32_SFLOAT, "VK_FORMAT_R32G32_SFLOAT"},
    {VK_FORMAT_R32G32B32_SFLOAT, "VK_FORMAT_R32G32B32_SFLOAT"},
    {VK_FORMAT_R32G32B32A32_SFLOAT, "VK_FORMAT_R32G32B32A32_SFLOAT"},
};

}  // namespace

const char* result_name(VkResult result) {
  return lookup(kResultNames, result, "an unnamed VkResult");
}

const char* format_name(VkFormat format) {
  return lookup(kFormatNames, format, "a VkFormat the runtime does not use");
}

Status check(VkResult result, const char* call, std::string_view what) {
  if (result == VK_SUCCESS) return {};
  // The number too, so results the table does not name stay identifiable.
  return make_error(Error::Kind::device, call,
                    std::string(what) + " failed: " + result_name(result) + " (" +
                        std::to_string(static_cast<int>(result)) + ")");
}

}  // namespace penumbra::vk
