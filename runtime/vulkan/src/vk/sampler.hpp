// Sampler: a sampler of the shader interface, created from the state a
// pass's reflection gives its texture (docs/shader-interface.md).
#pragma once

#include <vulkan/vulkan.h>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using Sampler = DeviceObject<VkSampler, vkDestroySampler>;

// Every sampler addresses clamp-to-edge.
struct SamplerDesc {
  VkFilter filter = VK_FILTER_NEAREST;  // minification and magnification
  // Levels past the base: 0 reads level 0 only (GL's non-mipmapped
  // minification); VK_LOD_CLAMP_NONE every level, the nearest one.
  float max_lod = 0.0f;
  bool comparison = false;     // compare LESS_OR_EQUAL: lit when reference <= texel
  bool greater_equal = false;  // with comparison: GREATER_OR_EQUAL (a reversed-Z map)
};

Result<Sampler> create_sampler(VkDevice device, const SamplerDesc& desc);

}  // namespace penumbra::vk
