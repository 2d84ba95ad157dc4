#include "device_selection.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::detail {
namespace {

std::string lowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

bool all_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::optional<std::size_t> first_containing(const std::vector<std::string>& names,
                                            std::string_view needle) {
  const std::string lower_needle = lowercase(needle);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (lowercase(names[i]).find(lower_needle) != std::string::npos) return i;
  }
  return std::nullopt;
}

std::string listing(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i ? ", " : "") + std::to_string(i) + ": " + names[i];
  }
  return text;
}

}  // namespace

Result<VkPhysicalDevice> select_physical_device(std::span<const VkPhysicalDevice> devices,
                                                std::string_view selector) {
  std::vector<std::string> names;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    names.emplace_back(properties.deviceName);
  }

  // The project's results are defined on lavapipe, so it wins by default.
  if (selector.empty()) return devices[first_containing(names, "llvmpipe").value_or(0)];

  std::optional<std::size_t> index;
  if (all_digits(selector)) {
    // Over-long digit strings are out of range, not an overflow.
    if (selector.size() < 10 && std::stoul(std::string(selector)) < names.size()) {
      index = std::stoul(std::string(selector));
    }
  } else {
    index = first_containing(names, selector);
  }
  if (index) return devices[*index];
  return make_error(
      Error::Kind::bad_input, "device '" + std::string(selector) + "'",
      "no Vulkan device matches; give an index or part of a name of one of: " + listing(names));
}

}  // namespace penumbra::detail
