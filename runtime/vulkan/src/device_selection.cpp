#include "device_selection.hpp"

#include <string>
#include <vector>

#include "penumbra/support/device_selector.hpp"

namespace penumbra::detail {

Result<VkPhysicalDevice> select_physical_device(std::span<const VkPhysicalDevice> devices,
                                                std::string_view selector) {
  std::vector<std::string> names;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    names.emplace_back(properties.deviceName);
  }

  // The project's results are defined on lavapipe, so it wins by default.
  if (selector.empty()) return devices[match_selector(names, "llvmpipe").value_or(0)];
  if (const auto index = match_selector(names, selector)) return devices[*index];
  return make_error(Error::Kind::bad_input, "device '" + std::string(selector) + "'",
                    "no Vulkan device matches; give an index or part of a name of one of: " +
                        list_choices(names));
}

}  // namespace penumbra::detail
