#include "vk/sampler.hpp"

#include "vk/check.hpp"

namespace penumbra::vk {

Result<Sampler> create_sampler(VkDevice device, SamplerKind kind) {
  const bool comparison = kind == SamplerKind::comparison;
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  // Linear filtering of a comparison sampler blends the four compare results:
  // the contract's bilinear comparison.
  info.magFilter = comparison ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.minFilter = info.magFilter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.compareEnable = comparison ? VK_TRUE : VK_FALSE;
  // Lit when reference <= stored depth (contract section 1).
  info.compareOp = comparison ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_NEVER;
  // Every level an image has: shadow_minmax is read at LOD l - 1 (with maxLod
  // 0 every read would clamp to level 0); single-level images clamp to 0.
  info.minLod = 0.0f;
  info.maxLod = VK_LOD_CLAMP_NONE;
  info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  VkSampler sampler = VK_NULL_HANDLE;
  PENUMBRA_TRY(
      check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler",
            comparison ? "creating the comparison sampler" : "creating the nearest sampler"));
  return Sampler(device, sampler);
}

}  // namespace penumbra::vk
