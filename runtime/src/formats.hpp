// The formats the runtime uses, and the check that a device supports them.
#pragma once

#include <vulkan/vulkan.h>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"

namespace penumbra::detail {

// Shadow map: depth image and its colour twin (docs/shader-interface.md).
inline constexpr VkFormat kMapDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kMapColourFormat = VK_FORMAT_R32_SFLOAT;
// Query pass: receivers in, visibility out.
inline constexpr VkFormat kReceiversFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kVisibilityFormat = VK_FORMAT_R32_SFLOAT;
// Vertex positions: light-view xyz (depth pass), clip-space xy (query pass).
inline constexpr VkFormat kDepthPositionFormat = VK_FORMAT_R32G32B32_SFLOAT;
inline constexpr VkFormat kQueryPositionFormat = VK_FORMAT_R32G32_SFLOAT;

// An Error naming the first format and feature the device lacks.
Status check_format_support(const vk::Device& device);

}  // namespace penumbra::detail
