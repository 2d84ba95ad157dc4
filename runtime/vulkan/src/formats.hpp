// The formats the runtime uses, and the check that a device supports them.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string_view>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/result.hpp"
#include "vk/device.hpp"

namespace penumbra::detail {

// Shadow map: depth image and its colour twin (docs/shader-interface.md).
inline constexpr VkFormat kMapDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kMapColourFormat = VK_FORMAT_R32_SFLOAT;
// Query pass: receivers in; out (visibility, texel reads).
inline constexpr VkFormat kReceiversFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kVisibilityFormat = VK_FORMAT_R32G32_SFLOAT;
// The min-max mip's levels: (min, max) of normalized depth.
inline constexpr VkFormat kMinmaxFormat = VK_FORMAT_R32G32_SFLOAT;
// A chain of screen passes: the factor and blur targets (factor, texel
// reads or 0), read by the next pass as screen_factor; scene_colour in; the
// composite out.
inline constexpr VkFormat kScreenFactorFormat = VK_FORMAT_R32G32_SFLOAT;
inline constexpr VkFormat kSceneColourFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kCompositeFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
// Vertex positions: light-view xyz (depth pass), clip-space xy (query pass).
inline constexpr VkFormat kDepthPositionFormat = VK_FORMAT_R32G32B32_SFLOAT;
inline constexpr VkFormat kQueryPositionFormat = VK_FORMAT_R32G32_SFLOAT;

// A pass's colour target as its checks see it: its format's name, for
// messages, and the components output 0 must have to fill it.
struct ColourTarget {
  std::string_view format;
  std::uint32_t components = 0;
};
inline constexpr ColourTarget kMapColourTarget{"R32_SFLOAT", 1};           // kMapColourFormat
inline constexpr ColourTarget kVisibilityTarget{"R32G32_SFLOAT", 2};       // kVisibilityFormat
inline constexpr ColourTarget kMinmaxTarget{"R32G32_SFLOAT", 2};           // kMinmaxFormat
inline constexpr ColourTarget kScreenFactorTarget{"R32G32_SFLOAT", 2};     // kScreenFactorFormat
inline constexpr ColourTarget kCompositeTarget{"R32G32B32A32_SFLOAT", 4};  // kCompositeFormat

// The Vulkan format of a TextureFormat (d32_float: D32_SFLOAT).
VkFormat vk_format(TextureFormat format);

// The depth image of a map in `format`: D32_SFLOAT, X8_D24_UNORM_PACK32 or
// D16_UNORM. Each stands for the reflection's d32_float.
VkFormat vk_depth_format(DepthFormat format);
// `format` as a DepthFormat; none for a colour format.
std::optional<DepthFormat> depth_format_of(VkFormat format);

// An Error naming the feature a map's depth image in `format` lacks: the
// depth pass's attachment, sampling, comparison and transfers.
Status check_depth_format(const vk::Device& device, VkFormat format);

// The TextureFormat that `target`'s API calls `api_name` (api_format()'s
// inverse), as index.json's reflection writes formats. A name the target
// does not use is a bad_input Error (where = `where`).
Result<TextureFormat> reflected_format(Target target, std::string_view api_name,
                                       std::string_view where);

// `format` in `target`'s API terms, or "an unknown format" when no TextureFormat
// format is a `format` image: for messages.
std::string_view api_name(Target target, VkFormat format);

// An Error naming the first format and feature the device lacks.
Status check_format_support(const vk::Device& device);

}  // namespace penumbra::detail
