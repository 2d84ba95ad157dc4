#include "formats.hpp"

#include <string>

#include "vk/check.hpp"

namespace penumbra::detail {
namespace {

constexpr TextureFormat kTextureFormats[] = {TextureFormat::r32_float, TextureFormat::rg32_float,
                                             TextureFormat::rgba32_float, TextureFormat::d32_float};

struct Requirement {
  VkFormat format;
  bool vertex_buffer;  // a buffer feature rather than an optimal-tiling image feature
  VkFormatFeatureFlags2 feature;
  const char* feature_name;
  const char* needed_for;
};

// Linear filtering of comparisons needs no SAMPLED_IMAGE_FILTER_LINEAR: that
// bit is about unfiltered reads, and lavapipe, for one, does not report it
// for D32_SFLOAT. Comparisons need SAMPLED_IMAGE_DEPTH_COMPARISON instead.
constexpr Requirement kRequirements[] = {
    {kMapDepthFormat, false, VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT,
     "DEPTH_STENCIL_ATTACHMENT", "the depth pass"},
    {kMapDepthFormat, false, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE",
     "shadow_depth and shadow_cmp"},
    {kMapDepthFormat, false, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT,
     "SAMPLED_IMAGE_DEPTH_COMPARISON", "the comparison sampler of shadow_cmp"},
    {kMapDepthFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST",
     "shadow map uploads"},
    {kMapDepthFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT, "TRANSFER_SRC",
     "depth readbacks of hardware-encoded maps"},
    {kMapColourFormat, false, VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT",
     "the depth pass"},
    {kMapColourFormat, false, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE",
     "shadow_depth without shadow_cmp"},
    {kMapColourFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT, "TRANSFER_SRC",
     "shadow map readbacks"},
    {kMapColourFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST",
     "shadow map uploads"},
    {kMinmaxFormat, false, VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT",
     "the query pass and the min-max mip build"},
    {kMinmaxFormat, false, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE",
     "shadow_minmax, minmax_source and screen_factor"},
    {kMinmaxFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT, "TRANSFER_SRC",
     "visibility and min-max readbacks, min-max level copies"},
    {kMinmaxFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST",
     "min-max level copies"},
    {kReceiversFormat, false, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE", "receivers"},
    {kReceiversFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST",
     "receiver and scene colour uploads"},
    {kCompositeFormat, false, VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT",
     "composite passes"},
    {kCompositeFormat, false, VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT, "TRANSFER_SRC",
     "composite readbacks"},
    {kDepthPositionFormat, true, VK_FORMAT_FEATURE_2_VERTEX_BUFFER_BIT, "VERTEX_BUFFER",
     "depth pass positions"},
    {kQueryPositionFormat, true, VK_FORMAT_FEATURE_2_VERTEX_BUFFER_BIT, "VERTEX_BUFFER",
     "query pass positions"},
};

struct FormatFeatures {
  VkFormatFeatureFlags2 optimal_tiling = 0;
  VkFormatFeatureFlags2 buffer = 0;
};

// Vulkan 1.3 reports 64-bit features. Before it, SAMPLED_IMAGE_DEPTH_COMPARISON
// did not exist and every sampled depth format allowed comparisons, so it is
// implied by SAMPLED_IMAGE there.
FormatFeatures features_of(const vk::Device& device, VkFormat format) {
  if (device.api_version() >= VK_API_VERSION_1_3) {
    VkFormatProperties3 properties3{};
    properties3.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3;
    VkFormatProperties2 properties2{};
    properties2.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2;
    properties2.pNext = &properties3;
    vkGetPhysicalDeviceFormatProperties2(device.physical(), format, &properties2);
    return {properties3.optimalTilingFeatures, properties3.bufferFeatures};
  }
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), format, &properties);
  FormatFeatures features{properties.optimalTilingFeatures, properties.bufferFeatures};
  if (features.optimal_tiling & VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT) {
    features.optimal_tiling |= VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT;
  }
  return features;
}

// An Error naming the device, `format` and the feature `requirement` asks
// of it, where the device lacks it.
Status require(const vk::Device& device, VkFormat format, const Requirement& requirement) {
  const FormatFeatures features = features_of(device, format);
  const VkFormatFeatureFlags2 supported =
      requirement.vertex_buffer ? features.buffer : features.optimal_tiling;
  if ((supported & requirement.feature) != 0) return {};
  return make_error(Error::Kind::device, "vkGetPhysicalDeviceFormatProperties",
                    std::string(device.properties().deviceName) + " does not support " +
                        vk::format_name(format) + " with " + requirement.feature_name + " (" +
                        (requirement.vertex_buffer ? "buffer" : "optimal tiling") + "), which " +
                        requirement.needed_for + " need(s)");
}

}  // namespace

VkFormat vk_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::r32_float:
      return VK_FORMAT_R32_SFLOAT;
    case TextureFormat::rg32_float:
      return VK_FORMAT_R32G32_SFLOAT;
    case TextureFormat::rgba32_float:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TextureFormat::d32_float:
      return VK_FORMAT_D32_SFLOAT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkFormat vk_depth_format(DepthFormat format) {
  switch (format) {
    case DepthFormat::d32_float:
      return VK_FORMAT_D32_SFLOAT;
    case DepthFormat::d24_unorm:
      return VK_FORMAT_X8_D24_UNORM_PACK32;
    case DepthFormat::d16_unorm:
      return VK_FORMAT_D16_UNORM;
  }
  return VK_FORMAT_UNDEFINED;
}

std::optional<DepthFormat> depth_format_of(VkFormat format) {
  for (const DepthFormat depth : kAllDepthFormats) {
    if (vk_depth_format(depth) == format) return depth;
  }
  return std::nullopt;
}

Result<TextureFormat> reflected_format(Target target, std::string_view api_name,
                                       std::string_view where) {
  if (auto format = parse_api_format(target, api_name)) return *format;
  return make_error(Error::Kind::bad_input, std::string(where),
                    "index.json's reflection gives the format '" + std::string(api_name) +
                        "', which is not a " + std::string(to_string(target)) +
                        " format of the shader contract (" + allowed_api_formats(target) + ")");
}

std::string_view api_name(Target target, VkFormat format) {
  for (TextureFormat known : kTextureFormats) {
    if (vk_format(known) == format) return api_format(target, known);
  }
  if (depth_format_of(format)) return vk::format_name(format);
  return "an unknown format";
}

Status check_depth_format(const vk::Device& device, VkFormat format) {
  for (const Requirement& requirement : kRequirements) {
    if (requirement.format == kMapDepthFormat) PENUMBRA_TRY(require(device, format, requirement));
  }
  return {};
}

Status check_format_support(const vk::Device& device) {
  static_assert(kVisibilityFormat == kMinmaxFormat && kScreenFactorFormat == kMinmaxFormat,
                "one RG32F requirement list serves the query, min-max and blur targets");
  static_assert(kSceneColourFormat == kReceiversFormat && kCompositeFormat == kReceiversFormat,
                "one RGBA32F requirement list serves receivers, scene colour and composite");
  for (const Requirement& requirement : kRequirements) {
    PENUMBRA_TRY(require(device, requirement.format, requirement));
  }
  return {};
}

}  // namespace penumbra::detail
