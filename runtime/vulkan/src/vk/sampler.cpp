#include "vk/sampler.hpp"

#include "vk/check.hpp"

namespace penumbra::vk {

Result<Sampler> create_sampler(VkDevice device, const SamplerDesc& desc) {
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  // Linear filtering of a comparison sampler blends the four compare results:
  // docs/shader-interface.md's bilinear comparison.
  info.magFilter = desc.filter;
  info.minFilter = desc.filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.compareEnable = desc.comparison ? VK_TRUE : VK_FALSE;
  info.compareOp = !desc.comparison     ? VK_COMPARE_OP_NEVER
                   : desc.greater_equal ? VK_COMPARE_OP_GREATER_OR_EQUAL
                                        : VK_COMPARE_OP_LESS_OR_EQUAL;
  info.minLod = 0.0f;
  info.maxLod = desc.max_lod;
  info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  VkSampler sampler = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler",
                     "creating a sampler"));
  return Sampler(device, sampler);
}

}  // namespace penumbra::vk
