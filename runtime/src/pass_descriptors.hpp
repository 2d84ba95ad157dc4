// PassDescriptors: the descriptor sets of one pass, pointing every planned
// binding at its resource, and the uniform buffers holding ShadowParams.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string_view>
#include <vector>

#include "binding_plan.hpp"
#include "context.hpp"
#include "pass_pipeline.hpp"
#include "shadow_map_images.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"

namespace penumbra::detail {

// What a pass can bind; absent resources are null.
struct PassResources {
  const ParamBlock* params = nullptr;
  const ShadowMapImages* shadow_map = nullptr;  // in its resting layouts
  bool map_comparison = true;  // offer shadow_map as shadow_cmp too, not only shadow_depth
  const vk::Image* receivers = nullptr;      // in SHADER_READ_ONLY_OPTIMAL
  const vk::Image* minmax_mip = nullptr;     // shadow_minmax, in kMinmaxLayout
  const vk::Image* minmax_source = nullptr;  // in SHADER_READ_ONLY_OPTIMAL
  const vk::Image* screen_factor = nullptr;  // in SHADER_READ_ONLY_OPTIMAL
  const vk::Image* scene_colour = nullptr;   // in SHADER_READ_ONLY_OPTIMAL

  // The interface names these resources serve, for plan_bindings().
  std::vector<std::string_view> available() const;
};

class PassDescriptors {
 public:
  // `plan` must come from plan_bindings() with `resources.available()`.
  // Each uniform block binding gets its own buffer, packed from the ParamBlock.
  static Result<PassDescriptors> create(const Context& context, const BindingPlan& plan,
                                        const PassPipeline& pipeline,
                                        const PassResources& resources, std::string_view pass);

  // One per set of the plan, set 0 first.
  const std::vector<VkDescriptorSet>& sets() const { return sets_; }

 private:
  PassDescriptors(std::vector<vk::Buffer> uniforms, std::optional<vk::DescriptorPool> pool,
                  std::vector<VkDescriptorSet> sets);

  std::vector<vk::Buffer> uniforms_;
  std::optional<vk::DescriptorPool> pool_;  // absent when the program binds nothing
  std::vector<VkDescriptorSet> sets_;
};

}  // namespace penumbra::detail
