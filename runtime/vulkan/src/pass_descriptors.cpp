#include "pass_descriptors.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "param_block.hpp"
#include "vk/descriptor_set.hpp"

namespace penumbra::detail {
namespace {

Result<vk::Buffer> create_uniforms(const Context& context, const PlannedBinding& binding,
                                   const ParamBlock& params, std::string_view pass) {
  auto bytes = pack_params(binding, params, pass);
  if (!bytes) return bytes.error();
  // A buffer cannot be empty, even for a block without members.
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes->size(), 16);
  auto buffer = vk::Buffer::create(*context.device, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   "the " + binding.name + " uniform buffer");
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

// The reflection's sampler state as Vulkan sampler parameters.
vk::SamplerDesc sampler_desc(const SamplerState& state) {
  vk::SamplerDesc desc;
  desc.filter = state.filter == Filter::linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  // The min-max mip is read at explicit levels (textureLod(shadow_minmax, uv, l - 1)).
  desc.max_lod = state.mip_filter == MipFilter::nearest ? VK_LOD_CLAMP_NONE : 0.0f;
  desc.comparison = state.comparison;
  desc.greater_equal = state.greater_equal;
  return desc;
}

// The offered image of the binding's texture in the format the reflection
// gives it.
Result<const OfferedImage*> find_image(const PassResources& resources,
                                       const PlannedBinding& binding, Target target,
                                       std::string_view pass) {
  const VkFormat format = vk_format(binding.format);
  std::string offered;
  for (const OfferedImage& image : resources.images) {
    if (image.texture != binding.texture->id) continue;
    const VkFormat held = image.image->desc().format;
    // A D24 or D16 map stands where the reflection says D32_SFLOAT: shaders
    // read every depth format as a float.
    if (held == format || (format == kMapDepthFormat && depth_format_of(held))) return &image;
    offered +=
        (offered.empty() ? "" : ", ") + std::string(api_name(target, image.image->desc().format));
  }
  if (offered.empty()) {
    return make_error(Error::Kind::bad_input, std::string(pass),
                      "'" + binding.name + "' has nothing to bind to in the " + std::string(pass) +
                          ", which binds: " + resources.available());
  }
  return make_error(Error::Kind::bad_input, std::string(pass),
                    "'" + binding.name + "' is " + std::string(api_format(target, binding.format)) +
                        " in index.json's reflection; the " + std::string(pass) + " has it as " +
                        offered);
}

// A constant texture's image, filled with the reflection's texels.
Result<vk::Image> create_constant(Context& context, const PlannedBinding& binding) {
  const TextureContents& contents = *binding.contents;
  const std::string what = "the " + binding.name + " texture";
  PENUMBRA_TRY(context.check_extent(static_cast<int>(contents.width),
                                    static_cast<int>(contents.height), binding.name));
  auto image = vk::Image::create(
      *context.device,
      {contents.width, contents.height, vk_format(binding.format),
       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT},
      what);
  if (!image) return image.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, *image, contents.texels,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, what));
  return std::move(*image);
}

// A separate image or sampler alone on its binding.
void write_separate(VkDevice device, VkDescriptorSet set, const PlannedBinding& binding,
                    VkImageView view, VkImageLayout layout, VkSampler sampler) {
  const VkDescriptorImageInfo info{sampler, view, layout};
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

void PassResources::offer(TextureId texture, const vk::Image& image, VkImageLayout layout) {
  images.push_back({texture, &image, layout});
}

void PassResources::offer_map(const ShadowMapImages& map, bool comparison) {
  offer(TextureId::shadow_depth, map.depth, kMapDepthLayout);
  offer(TextureId::shadow_depth, map.colour, kMapColourLayout);
  if (comparison) offer(TextureId::shadow_cmp, map.depth, kMapDepthLayout);
  if (map.minmax) offer(TextureId::shadow_minmax, map.minmax->image, kMinmaxLayout);
}

std::string PassResources::available() const {
  std::string names = params ? std::string(kParamsBlock) : "";
  for (const TextureDescription& texture : all_textures()) {
    const bool offered = std::any_of(images.begin(), images.end(), [&](const OfferedImage& i) {
      return i.texture == texture.id;
    });
    if (offered) names += (names.empty() ? "" : ", ") + std::string(texture.name);
  }
  return names.empty() ? "nothing" : names;
}

Result<PassDescriptors> PassDescriptors::create(Context& context, const BindingPlan& plan,
                                                const PassPipeline& pipeline,
                                                const PassResources& resources, Target target,
                                                std::string_view pass) {
  PassDescriptors out;
  if (plan.set_count == 0) return out;
  const VkDevice device = context.device->get();
  auto pool = create_pool(device, plan);
  if (!pool) return pool.error();
  for (std::uint32_t set = 0; set < plan.set_count; ++set) {
    auto allocated = pool->allocate(pipeline.set_layout(set));
    if (!allocated) return allocated.error();
    out.sets_.push_back(*allocated);
  }
  out.pool_.emplace(std::move(*pool));

  for (const PlannedBinding& binding : plan.bindings) {
    const VkDescriptorSet set = out.sets_[binding.set];
    if (binding.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
      if (!resources.params) {
        return make_error(Error::Kind::bad_input, std::string(pass),
                          "'" + binding.name + "' has nothing to bind to in the " +
                              std::string(pass) + ", which binds: " + resources.available());
      }
      auto buffer = create_uniforms(context, binding, *resources.params, pass);
      if (!buffer) return buffer.error();
      vk::write_uniform_buffer(device, set, binding.binding, buffer->get(), buffer->size());
      out.uniforms_.push_back(std::move(*buffer));
      continue;
    }
    VkSampler sampler = VK_NULL_HANDLE;
    if (binding.sampler) {
      auto created = vk::create_sampler(device, sampler_desc(*binding.sampler));
      if (!created) return created.error();
      sampler = created->get();
      out.samplers_.push_back(std::move(*created));
    }
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (binding.contents) {
      auto image = create_constant(context, binding);
      if (!image) return image.error();
      out.constants_.push_back(std::move(*image));
      view = out.constants_.back().view();
      layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    } else if (binding.texture) {
      const OfferedImage* image = nullptr;
      PENUMBRA_TRY_ASSIGN(image, find_image(resources, binding, target, pass));
      view = image->image->view();
      layout = image->layout;
    }
    if (binding.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER) {
      vk::write_sampled_image(device, set, binding.binding, view, layout, sampler);
    } else {
      write_separate(device, set, binding, view, layout, sampler);
    }
  }
  return out;
}

}  // namespace penumbra::detail
