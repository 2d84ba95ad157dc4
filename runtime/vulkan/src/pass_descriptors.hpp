// PassDescriptors: the descriptor sets of one pass, pointing every planned
// binding at its resource, with the uniform buffers and samplers they use.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "context.hpp"
#include "pass_pipeline.hpp"
#include "reflection_binding.hpp"
#include "shadow_map_images.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/image.hpp"
#include "vk/sampler.hpp"

namespace penumbra::detail {

// An image a pass can bind as one of shader_contract.hpp's textures.
struct OfferedImage {
  TextureId texture;
  const vk::Image* image = nullptr;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // the layout it rests in
};

// What a pass can bind. A texture may be offered as more than one image:
// the reflection's format picks one (the map as shadow_depth: its D32 depth
// image or its R32F colour twin, the Direct3D 9 style).
struct PassResources {
  const ParamBlock* params = nullptr;
  std::vector<OfferedImage> images;

  void offer(TextureId texture, const vk::Image& image, VkImageLayout layout);
  // The map as shadow_depth (both images) and, with `comparison`, as
  // shadow_cmp (its depth image); its min-max mip, when built, as shadow_minmax.
  void offer_map(const ShadowMapImages& map, bool comparison);
  // "ShadowParams, shadow_depth, receivers": what the pass binds, for messages.
  std::string available() const;
};

class PassDescriptors {
 public:
  // Each uniform buffer is packed from the ParamBlock; each texture is the
  // offered image of its name and format, or for a constant texture an
  // image created and filled from the reflection's contents; each sampler
  // is created from the reflection's state. Errors (bad_input, where = `pass`) name a texture
  // the pass has no image for.
  static Result<PassDescriptors> create(Context& context, const BindingPlan& plan,
                                        const PassPipeline& pipeline,
                                        const PassResources& resources, Target target,
                                        std::string_view pass);

  // One per set of the plan, set 0 first.
  const std::vector<VkDescriptorSet>& sets() const { return sets_; }

 private:
  PassDescriptors() = default;

  std::vector<vk::Buffer> uniforms_;
  std::vector<vk::Image> constants_;  // the constant textures' images
  std::vector<vk::Sampler> samplers_;
  std::optional<vk::DescriptorPool> pool_;  // absent when the program binds nothing
  std::vector<VkDescriptorSet> sets_;
};

}  // namespace penumbra::detail
