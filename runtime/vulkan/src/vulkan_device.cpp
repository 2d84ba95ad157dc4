#include "vulkan_device.hpp"

#include <string>
#include <utility>

#include "depth_pass.hpp"
#include "formats.hpp"
#include "image_transfer.hpp"
#include "minmax_build.hpp"
#include "pass.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "screen_inputs.hpp"
#include "shadow_map_transfer.hpp"

namespace penumbra::detail {
namespace {

constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

// A full-screen pass's or a surface's colour target: its Vulkan format and
// what its checks call it.
struct ColourFormat {
  VkFormat format;
  ColourTarget target;
};

ColourFormat colour_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::rg32_float:
      return {VK_FORMAT_R32G32_SFLOAT, kVisibilityTarget};
    case TextureFormat::r32_float:
      return {kMapColourFormat, kMapColourTarget};
    default:
      return {kCompositeFormat, kCompositeTarget};
  }
}

std::vector<float> flatten(std::span<const std::array<float, 3>> triangles) {
  std::vector<float> positions;
  positions.reserve(triangles.size() * 3);
  for (const auto& vertex : triangles)
    positions.insert(positions.end(), vertex.begin(), vertex.end());
  return positions;
}

}  // namespace

runtime::Program VulkanDevice::load(const PassProgram& program) {
  programs_.push_back(&program);
  return runtime::Program{static_cast<int>(programs_.size())};
}

runtime::Texture VulkanDevice::hold(Held held, int width, int height) {
  const int id = next_id_++;
  textures_.emplace(id, std::move(held));
  return runtime::Texture{id, width, height};
}

runtime::Texture VulkanDevice::adopt(ShadowMapImages& map) {
  const VkExtent2D size = map.colour.extent();
  Held held;
  held.map = &map;
  return hold(std::move(held), static_cast<int>(size.width), static_cast<int>(size.height));
}

std::optional<runtime::Texture> VulkanDevice::adopt_mip(ShadowMapImages& map) {
  if (!map.minmax) return std::nullopt;
  Held held;
  held.map = &map;
  held.mip = true;
  const LevelSize first = map.minmax->sizes.front();
  return hold(std::move(held), first.width, first.height);
}

std::unique_ptr<ShadowMapImages> VulkanDevice::take_map(runtime::Texture map) {
  auto found = textures_.find(map.id);
  if (found == textures_.end()) return nullptr;
  std::unique_ptr<ShadowMapImages> images = std::move(found->second.owned_map);
  textures_.erase(found);
  return images;
}

Result<const VulkanDevice::Held*> VulkanDevice::find(runtime::Texture texture,
                                                     std::string_view where) const {
  const auto found = textures_.find(texture.id);
  if (found == textures_.end()) {
    return make_error(Error::Kind::internal, std::string(where),
                      "texture " + std::to_string(texture.id) + " is not on this device");
  }
  return &found->second;
}

Result<runtime::Texture> VulkanDevice::upload(TextureId as, const FloatImage& image) {
  Held held;
  switch (as) {
    case TextureId::shadow_depth:
    case TextureId::shadow_cmp:
    case TextureId::camera_depth: {
      // The map's two images; a camera's depth as an engine's depth pass
      // would leave it: a depth image and the R32F twin Direct3D 9 draws.
      PENUMBRA_TRY_ASSIGN(held.owned_map, upload_shadow_map(context_, image));
      held.map = held.owned_map.get();
      break;
    }
    case TextureId::receivers: {
      PENUMBRA_TRY_ASSIGN(held.image, upload_receivers(context_, image));
      held.components = 4;
      break;
    }
    case TextureId::scene_colour: {
      PENUMBRA_TRY_ASSIGN(held.image, upload_scene_colour(context_, image));
      held.components = 4;
      break;
    }
    default:
      return make_error(Error::Kind::bad_input, std::string(describe(as).name),
                        "is drawn by a pass or filled from the reflection, not uploaded");
  }
  return hold(std::move(held), image.width, image.layer_height());
}

Status VulkanDevice::offer(const runtime::Draw& draw, PassResources& resources) const {
  for (const runtime::Offer& offer : draw.inputs) {
    PENUMBRA_TRY_ASSIGN(const Held* held, find(offer.texture, draw.where));
    if (held->mip) {
      resources.offer(offer.as, held->map->minmax->image, kMinmaxLayout);
    } else if (held->map) {
      // shadow_depth (and camera_depth) as either image, the reflection's
      // format choosing; shadow_cmp as the depth image.
      resources.offer(offer.as, held->map->depth, kMapDepthLayout);
      if (offer.as != TextureId::shadow_cmp) {
        resources.offer(offer.as, held->map->colour, kMapColourLayout);
      }
    } else {
      resources.offer(offer.as, *held->image, kRead);
    }
  }
  return {};
}

Result<runtime::Drawn> VulkanDevice::draw(const runtime::Draw& draw) {
  if (draw.program.id < 1 || draw.program.id > static_cast<int>(programs_.size())) {
    return make_error(Error::Kind::internal, draw.where, "the program is not on this device");
  }
  const PassProgram& program = *programs_[static_cast<std::size_t>(draw.program.id - 1)];
  PassResources resources;
  resources.params = &draw.params;
  PENUMBRA_TRY(offer(draw, resources));
  if (draw.pass == PassKind::depth) return draw_map(draw, program);
  return draw_colour(draw, program, resources);
}

Result<runtime::Drawn> VulkanDevice::draw_map(const runtime::Draw& draw,
                                              const PassProgram& program) {
  Held held;
  PENUMBRA_TRY_ASSIGN(held.owned_map, render_depth(context_, program, draw.triangles, draw.width,
                                                   draw.height, draw.params, draw.depth_format));
  held.map = held.owned_map.get();
  const std::optional<double> gpu_ms = held.map->depth_gpu_ms;
  return runtime::Drawn{hold(std::move(held), draw.width, draw.height), gpu_ms};
}

Result<runtime::Drawn> VulkanDevice::draw_colour(const runtime::Draw& draw,
                                                 const PassProgram& program,
                                                 PassResources& resources) {
  // A pass's target is the model's; an engine's own program's is RGBA.
  const ColourFormat format =
      colour_format(draw.pass ? describe(*draw.pass).output.format : TextureFormat::rgba32_float);
  PENUMBRA_TRY(context_.check_extent(draw.width, draw.height, draw.where));
  const auto w = static_cast<std::uint32_t>(draw.width);
  const auto h = static_cast<std::uint32_t>(draw.height);
  const std::string what = "the " + draw.where + "'s target";
  PENUMBRA_TRY_ASSIGN(vk::Image colour, vk::Image::create(*context_.device,
                                                          {w, h, format.format,
                                                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                                               VK_IMAGE_USAGE_SAMPLED_BIT |
                                                               VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                                           VK_IMAGE_ASPECT_COLOR_BIT},
                                                          what));
  const bool geometry = !draw.triangles.empty();
  std::optional<vk::Image> depth;
  if (geometry) {
    // The camera's own depth buffer: the nearest surface wins, as in an engine.
    PENUMBRA_TRY_ASSIGN(depth, vk::Image::create(*context_.device,
                                                 {w, h, kMapDepthFormat,
                                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                                  VK_IMAGE_ASPECT_DEPTH_BIT},
                                                 "the " + draw.where + "'s depth image"));
  }
  const std::vector<float> positions = flatten(draw.triangles);
  PassDraw pass;
  pass.program = &program;
  pass.shape = {draw.where,
                format.target,
                geometry ? kDepthPositionFormat : kQueryPositionFormat,
                geometry ? 3u : 2u,
                geometry,
                false,
                false};
  pass.resources = resources;
  pass.positions = geometry ? std::span<const float>(positions) : kFullScreenTriangle;
  pass.target = sampled_target(colour);
  if (depth) {
    pass.target.depth = &*depth;
    pass.target.depth_final = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  }
  PENUMBRA_TRY_ASSIGN(std::optional<double> gpu_ms, draw_pass(context_, pass));
  Held held;
  held.image = std::move(colour);
  held.components = format.target.components;
  return runtime::Drawn{hold(std::move(held), draw.width, draw.height), gpu_ms};
}

Result<runtime::Texture> VulkanDevice::gather_mip(runtime::Texture map,
                                                  std::span<const runtime::Texture> levels) {
  PENUMBRA_TRY_ASSIGN(const Held* held_map, find(map, "the min-max mip"));
  if (!held_map->map || held_map->mip) {
    return make_error(Error::Kind::internal, "the min-max mip", "gathered onto a non-map");
  }
  std::vector<const vk::Image*> images;
  for (runtime::Texture level : levels) {
    PENUMBRA_TRY_ASSIGN(const Held* held, find(level, "the min-max mip"));
    images.push_back(&*held->image);
  }
  ShadowMapImages& images_of_map = *held_map->map;
  PENUMBRA_TRY_ASSIGN(images_of_map.minmax, gather_minmax(context_, map.width, map.height, images));
  return *adopt_mip(images_of_map);
}

Result<std::vector<FloatImage>> VulkanDevice::read_all(std::span<const runtime::Texture> textures) {
  std::vector<FloatImage> images;
  for (runtime::Texture texture : textures) {
    PENUMBRA_TRY_ASSIGN(FloatImage image, read_one(texture));
    images.push_back(std::move(image));
  }
  return images;
}

Result<FloatImage> VulkanDevice::read_one(runtime::Texture texture) {
  PENUMBRA_TRY_ASSIGN(const Held* held, find(texture, "readback"));
  if (held->mip) {
    PENUMBRA_TRY_ASSIGN(std::vector<FloatImage> mip, read_minmax(context_, *held->map));
    return std::move(mip.front());
  }
  if (held->map) return read_shadow_map(context_, *held->map);
  FloatImage out(texture.width, texture.height, static_cast<int>(held->components));
  PENUMBRA_TRY_ASSIGN(out.data, read_image(*context_.device, *context_.commands, *held->image,
                                           kRead, held->components, "a pass's target"));
  return out;
}

void VulkanDevice::release(runtime::Texture texture) {
  textures_.erase(texture.id);
}

}  // namespace penumbra::detail
