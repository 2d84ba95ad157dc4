// The device side of a ShadowMap.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <optional>
#include <vector>

#include "context.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// Between engine calls the images rest in these layouts, ready for sampling;
// every operation on them starts and ends there.
inline constexpr VkImageLayout kMapDepthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
inline constexpr VkImageLayout kMapColourLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
inline constexpr VkImageLayout kMinmaxLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

// The min-max mip (docs/runtime.md, "The min-max mip"): hierarchy level l
// (1..N) in mip level l - 1 of a 2^(N-1) x 2^(N-1) RG32F image, at texels
// [0, sizes[l - 1]); the rest of each level is padding.
struct MinmaxMip {
  vk::Image image;
  std::vector<LevelSize> sizes;  // minmax_level_sizes of the map
};

struct ShadowMapImages {
  // First, so it is released after both images. Also identifies the only
  // Context that may use them: the one with the same device.
  std::shared_ptr<const vk::Device> device;
  vk::Image depth;                     // D32_SFLOAT, or a unorm depth format
  vk::Image colour;                    // R32_SFLOAT, the shader's depth output
  std::optional<MinmaxMip> minmax;     // once built (Engine::build_minmax)
  std::optional<double> depth_gpu_ms;  // the depth pass that drew it, when timed
};

// Both images, uninitialized (layout UNDEFINED), usable as attachments,
// sampled images and transfer source/destination; the depth image in
// `depth_format`, an Error where the device cannot use it so. With `layers`
// (map_layout array), both are 2D arrays of that many layers, to be
// uploaded and sampled, not drawn into.
Result<std::unique_ptr<ShadowMapImages>> create_shadow_map_images(
    const Context& context, int width, int height,
    DepthFormat depth_format = DepthFormat::d32_float, int layers = 0);

}  // namespace penumbra::detail
