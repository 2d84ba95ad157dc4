#include "pass_descriptors.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "param_block.hpp"
#include "vk/descriptor_set.hpp"

namespace penumbra::detail {
namespace {

Result<vk::Buffer> create_uniforms(const Context& context, const ParamsLayout& layout,
                                   const ParamBlock& params, std::string_view pass) {
  auto bytes = pack_params(layout, params, pass);
  if (!bytes) return bytes.error();
  // A buffer cannot be empty, even for a block without members.
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes->size(), 16);
  auto buffer = vk::Buffer::create(*context.device, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   "the " + layout.block + " uniform buffer");
  if (!buffer) return buffer.error();
  std::memcpy(buffer->bytes().data(), bytes->data(), bytes->size());
  return std::move(*buffer);
}

Result<vk::DescriptorPool> create_pool(VkDevice device, const BindingPlan& plan) {
  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const PlannedBinding& binding : plan.bindings) ++counts[binding.type];
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, count] : counts) sizes.push_back({type, count});
  return vk::DescriptorPool::create(device, sizes, plan.set_count);
}

// The image (in the layout it rests in) and the sampler a role binds.
struct RoleImage {
  VkImageView view = VK_NULL_HANDLE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkSampler sampler = VK_NULL_HANDLE;
};

RoleImage role_image(const Context& context, const PassResources& resources, BindingRole role) {
  const ShadowMapImages* map = resources.shadow_map;
  switch (role) {
    case BindingRole::map_depth:
      return {map->depth.view(), kMapDepthLayout, context.nearest.get()};
    case BindingRole::map_colour:
      return {map->colour.view(), kMapColourLayout, context.nearest.get()};
    case BindingRole::map_comparison:
      return {map->depth.view(), kMapDepthLayout, context.comparison.get()};
    case BindingRole::receivers:
      return {resources.receivers->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              context.nearest.get()};
    case BindingRole::minmax_mip:
      return {resources.minmax_mip->view(), kMinmaxLayout, context.nearest.get()};
    case BindingRole::minmax_source:
      return {resources.minmax_source->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              context.nearest.get()};
    case BindingRole::screen_factor:
      return {resources.screen_factor->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              context.nearest.get()};
    case BindingRole::scene_colour:
      return {resources.scene_colour->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              context.nearest.get()};
    case BindingRole::params:
      break;
  }
  return {};
}

// A separate image or sampler takes its half of the role's pair.
void write_separate(VkDevice device, VkDescriptorSet set, const PlannedBinding& binding,
                    const RoleImage& image) {
  const bool is_sampler = binding.type == VK_DESCRIPTOR_TYPE_SAMPLER;
  const VkDescriptorImageInfo info{is_sampler ? image.sampler : VK_NULL_HANDLE,
                                   is_sampler ? VK_NULL_HANDLE : image.view, image.layout};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set;
  write.dstBinding = binding.binding;
  write.descriptorCount = 1;
  write.descriptorType = binding.type;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

}  // namespace

std::vector<std::string_view> PassResources::available() const {
  std::vector<std::string_view> names;
  if (params) names.push_back(kParamsBlock);
  if (shadow_map) names.push_back(kShadowDepth);
  if (shadow_map && map_comparison) names.push_back(kShadowCmp);
  if (receivers) names.push_back(kReceivers);
  if (minmax_mip) names.push_back(kShadowMinmax);
  if (minmax_source) names.push_back(kMinmaxSource);
  if (screen_factor) names.push_back(kScreenFactor);
  if (scene_colour) names.push_back(kSceneColour);
  return names;
}

Result<PassDescriptors> PassDescriptors::create(const Context& context, const BindingPlan& plan,
                                                const PassPipeline& pipeline,
                                                const PassResources& resources,
                                                std::string_view pass) {
  if (plan.set_count == 0) return PassDescriptors({}, std::nullopt, {});
  const VkDevice device = context.device->get();
  auto pool = create_pool(device, plan);
  if (!pool) return pool.error();
  std::vector<VkDescriptorSet> sets;
  for (std::uint32_t set = 0; set < plan.set_count; ++set) {
    auto allocated = pool->allocate(pipeline.set_layout(set));
    if (!allocated) return allocated.error();
    sets.push_back(*allocated);
  }

  std::vector<vk::Buffer> uniforms;
  for (const PlannedBinding& binding : plan.bindings) {
    const VkDescriptorSet set = sets[binding.set];
    if (binding.role == BindingRole::params) {
      auto buffer = create_uniforms(context, binding.params, *resources.params, pass);
      if (!buffer) return buffer.error();
      vk::write_uniform_buffer(device, set, binding.binding, buffer->get(), buffer->size());
      uniforms.push_back(std::move(*buffer));
      continue;
    }
    const RoleImage image = role_image(context, resources, binding.role);
    if (binding.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER) {
      vk::write_sampled_image(device, set, binding.binding, image.view, image.layout,
                              image.sampler);
    } else {
      write_separate(device, set, binding, image);
    }
  }
  return PassDescriptors(std::move(uniforms), std::move(*pool), std::move(sets));
}

PassDescriptors::PassDescriptors(std::vector<vk::Buffer> uniforms,
                                 std::optional<vk::DescriptorPool> pool,
                                 std::vector<VkDescriptorSet> sets)
    : uniforms_(std::move(uniforms)), pool_(std::move(pool)), sets_(std::move(sets)) {}

}  // namespace penumbra::detail
