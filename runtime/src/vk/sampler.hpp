// Sampler: the two samplers of the shader interface (docs/shader-interface.md).
#pragma once

#include <vulkan/vulkan.h>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using Sampler = DeviceObject<VkSampler, vkDestroySampler>;

enum class SamplerKind {
  nearest,     // point sampling, nearest mip, clamp-to-edge: shadow_depth, receivers,
               // shadow_minmax (every level) and minmax_source
  comparison,  // LESS_OR_EQUAL comparison, linear filter, clamp-to-edge: shadow_cmp
};

Result<Sampler> create_sampler(VkDevice device, SamplerKind kind);

}  // namespace penumbra::vk
