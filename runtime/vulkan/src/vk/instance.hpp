// Instance: the VkInstance, with the Khronos validation layer when asked for
// and installed.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::vk {

class Instance {
 public:
  // The newest Vulkan version the runtime uses (VkFormatProperties3); it runs
  // on older devices at their own version.
  static constexpr std::uint32_t kApiVersion = VK_API_VERSION_1_3;

  // With `validation`, enables VK_LAYER_KHRONOS_validation and VK_EXT_debug_utils
  // when present; when absent, warns through `diagnostics` and goes on without.
  static Result<std::shared_ptr<const Instance>> create(bool validation,
                                                        const DiagnosticConsumer& diagnostics);
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;
  ~Instance();

  VkInstance get() const { return instance_; }
  // True when the validation layer and debug utils are enabled.
  bool validation_enabled() const { return validation_; }
  // Every physical device; an Error when there is none.
  Result<std::vector<VkPhysicalDevice>> physical_devices() const;

 private:
  Instance(VkInstance instance, bool validation) : instance_(instance), validation_(validation) {}

  VkInstance instance_;
  bool validation_;
};

}  // namespace penumbra::vk
