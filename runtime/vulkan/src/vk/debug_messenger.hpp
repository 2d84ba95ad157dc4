// DebugMessenger: routes validation-layer warnings and errors to a callback.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>

#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::vk {

class DebugMessenger {
 public:
  using Sink = std::function<void(Severity, const std::string&)>;

  // Needs an instance created with VK_EXT_debug_utils. `sink` receives each
  // warning and error message on the thread that made the offending call.
  static Result<DebugMessenger> create(VkInstance instance, Sink sink);
  DebugMessenger(DebugMessenger&& other) noexcept;
  DebugMessenger& operator=(DebugMessenger&&) = delete;
  DebugMessenger(const DebugMessenger&) = delete;
  DebugMessenger& operator=(const DebugMessenger&) = delete;
  ~DebugMessenger();

 private:
  DebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger,
                 std::unique_ptr<Sink> sink);

  VkInstance instance_;
  VkDebugUtilsMessengerEXT messenger_;
  std::unique_ptr<Sink> sink_;  // on the heap: the layer holds its address
};

}  // namespace penumbra::vk
