#include "pass_descriptors.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>

#include "param_block.hpp"
#include "vk/descriptor_set.hpp"

namespace penumbra::detail {
namespace {

Result<std::optional<vk::Buffer>> create_uniforms(const Context& context, const BindingPlan& plan,
                                                  const ParamBlock& params, std::string_view pass) {
  const bool uses_params = std::any_of(plan.bindings.begin(), plan.bindings.end(),
                                       [](const auto& b) { return b.role == BindingRole::params; });
  if (!uses_params) return std::optional<vk::Buffer>();
  auto bytes = pack_params(plan.params, params, pass);
  if (!bytes) return bytes.error();
  // A buffer cannot be empty, even for a block without members.
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes->size(), 16);
  auto buffer = vk::Buffer::create(*context.device, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   "the ShadowParams uniform buffer");
  if (!buffer) return buffer.error();
  std::memcpy(buffer->bytes().data(), bytes->data(), bytes->size());
  return std::optional<vk::Buffer>(std::move(*buffer));
}

Result<vk::DescriptorPool> create_pool(VkDevice device, const BindingPlan& plan) {
  std::uint32_t buffers = 0;
  std::uint32_t images = 0;
  for (const PlannedBinding& binding : plan.bindings) {
    ++(binding.role == BindingRole::params ? buffers : images);
  }
  std::vector<VkDescriptorPoolSize> sizes;
  if (buffers) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffers});
  if (images) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images});
  return vk::DescriptorPool::create(device, sizes, plan.set_count);
}

}  // namespace

std::vector<std::string_view> PassResources::available() const {
  std::vector<std::string_view> names;
  if (params) names.push_back(kParamsBlock);
  if (shadow_map) {
    names.push_back(kShadowDepth);
    names.push_back(kShadowCmp);
  }
  if (receivers) names.push_back(kReceivers);
  return names;
}

Result<PassDescriptors> PassDescriptors::create(const Context& context, const BindingPlan& plan,
                                                const PassPipeline& pipeline,
                                                const PassResources& resources,
                                                std::string_view pass) {
  if (plan.set_count == 0) return PassDescriptors(std::nullopt, std::nullopt, {});
  auto uniforms = create_uniforms(context, plan, *resources.params, pass);
  if (!uniforms) return uniforms.error();
  const VkDevice device = context.device->get();
  auto pool = create_pool(device, plan);
  if (!pool) return pool.error();
  std::vector<VkDescriptorSet> sets;
  for (std::uint32_t set = 0; set < plan.set_count; ++set) {
    auto allocated = pool->allocate(pipeline.set_layout(set));
    if (!allocated) return allocated.error();
    sets.push_back(*allocated);
  }

  for (const PlannedBinding& binding : plan.bindings) {
    const VkDescriptorSet set = sets[binding.set];
    const ShadowMapImages* map = resources.shadow_map;
    switch (binding.role) {
      case BindingRole::params:
        vk::write_uniform_buffer(device, set, binding.binding, (*uniforms)->get(),
                                 (*uniforms)->size());
        break;
      case BindingRole::map_depth:
        vk::write_sampled_image(device, set, binding.binding, map->depth.view(), kMapDepthLayout,
                                context.nearest.get());
        break;
      case BindingRole::map_colour:
        vk::write_sampled_image(device, set, binding.binding, map->colour.view(), kMapColourLayout,
                                context.nearest.get());
        break;
      case BindingRole::map_comparison:
        vk::write_sampled_image(device, set, binding.binding, map->depth.view(), kMapDepthLayout,
                                context.comparison.get());
        break;
      case BindingRole::receivers:
        vk::write_sampled_image(device, set, binding.binding, resources.receivers->view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, context.nearest.get());
        break;
    }
  }
  return PassDescriptors(std::move(*uniforms), std::move(*pool), std::move(sets));
}

PassDescriptors::PassDescriptors(std::optional<vk::Buffer> uniforms,
                                 std::optional<vk::DescriptorPool> pool,
                                 std::vector<VkDescriptorSet> sets)
    : uniforms_(std::move(uniforms)), pool_(std::move(pool)), sets_(std::move(sets)) {}

}  // namespace penumbra::detail
