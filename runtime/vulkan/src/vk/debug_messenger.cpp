#include "vk/debug_messenger.hpp"

#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL forward_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                               VkDebugUtilsMessageTypeFlagsEXT,
                                               const VkDebugUtilsMessengerCallbackDataEXT* data,
                                               void* user_data) {
  const auto& sink = *static_cast<const DebugMessenger::Sink*>(user_data);
  const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  sink(error ? Severity::error : Severity::warning, data->pMessage ? data->pMessage : "");
  // VK_FALSE: the call that triggered the message goes on; the runtime fails it afterwards.
  return VK_FALSE;
}

// Extension entry points are not exported by the loader; look them up.
template <typename Function>
Function instance_function(VkInstance instance, const char* name) {
  return reinterpret_cast<Function>(vkGetInstanceProcAddr(instance, name));
}

}  // namespace

Result<DebugMessenger> DebugMessenger::create(VkInstance instance, Sink sink) {
  const auto create_messenger = instance_function<PFN_vkCreateDebugUtilsMessengerEXT>(
      instance, "vkCreateDebugUtilsMessengerEXT");
  if (!create_messenger) {
    return make_error(Error::Kind::device, "vkGetInstanceProcAddr",
                      "vkCreateDebugUtilsMessengerEXT is missing although "
                      "VK_EXT_debug_utils is enabled");
  }
  auto owned_sink = std::make_unique<Sink>(std::move(sink));
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = forward_message;
  info.pUserData = owned_sink.get();
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(create_messenger(instance, &info, nullptr, &messenger),
                     "vkCreateDebugUtilsMessengerEXT", "creating the validation message callback"));
  return DebugMessenger(instance, messenger, std::move(owned_sink));
}

DebugMessenger::DebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger,
                               std::unique_ptr<Sink> sink)
    : instance_(instance), messenger_(messenger), sink_(std::move(sink)) {}

DebugMessenger::DebugMessenger(DebugMessenger&& other) noexcept
    : instance_(other.instance_),
      messenger_(std::exchange(other.messenger_, VK_NULL_HANDLE)),
      sink_(std::move(other.sink_)) {}

DebugMessenger::~DebugMessenger() {
  if (messenger_ == VK_NULL_HANDLE) return;
  const auto destroy_messenger = instance_function<PFN_vkDestroyDebugUtilsMessengerEXT>(
      instance_, "vkDestroyDebugUtilsMessengerEXT");
  if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
}

}  // namespace penumbra::vk
