#include "gl_device.hpp"

#include <utility>

#include "context_info.hpp"
#include "full_screen_draw.hpp"
#include "gl_check.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "surface_pass.hpp"
#include "textures.hpp"

namespace penumbra::gl {

Result<runtime::Program> GlDevice::load(const GlPass& pass, PassKind kind) {
  PENUMBRA_TRY_ASSIGN(PassProgram prepared, prepare_pass(pass, kind));
  programs_.push_back(std::move(prepared));
  return runtime::Program{static_cast<int>(programs_.size())};
}

Result<runtime::Program> GlDevice::load_surface(const GlPass& pass, std::string where) {
  PENUMBRA_TRY_ASSIGN(PassProgram prepared, prepare_program(pass, std::move(where), 3));
  programs_.push_back(std::move(prepared));
  return runtime::Program{static_cast<int>(programs_.size())};
}

const PassProgram& GlDevice::program(runtime::Program program) const {
  return programs_.at(static_cast<std::size_t>(program.id - 1));
}

runtime::Texture GlDevice::hold(Held held, int width, int height) {
  const int id = next_id_++;
  textures_.emplace(id, std::move(held));
  return runtime::Texture{id, width, height};
}

Result<GlDevice::Held*> GlDevice::find(runtime::Texture texture, std::string_view where) {
  const auto found = textures_.find(texture.id);
  if (found == textures_.end()) {
    return make_error(Error::Kind::internal, std::string(where),
                      "texture " + std::to_string(texture.id) + " is not on this device");
  }
  return &found->second;
}

Result<runtime::Texture> GlDevice::upload_map(const FloatImage& normalized_depth,
                                              DepthFormat format) {
  PENUMBRA_TRY(check_shadow_map(normalized_depth));
  Held held;
  held.image = std::make_unique<FloatImage>(normalized_depth);
  held.depth = format;
  return hold(std::move(held), normalized_depth.width, normalized_depth.layer_height());
}

Result<runtime::Texture> GlDevice::upload(TextureId as, const FloatImage& image) {
  // The map and the camera's depth as a map is checked; the receivers and
  // the scene colour by the caller, against each other.
  if (as == TextureId::shadow_depth || as == TextureId::shadow_cmp ||
      as == TextureId::camera_depth) {
    return upload_map(image, DepthFormat::d32_float);
  }
  Held held;
  held.image = std::make_unique<FloatImage>(image);
  return hold(std::move(held), image.width, image.height);
}

GlDevice::GlDevice() : software_(current_context_info().renderer.starts_with("llvmpipe")) {}

// Each draw reads only what it is offered; the uploads stay for the next.
Status GlDevice::offer(const runtime::Draw& draw) {
  inputs_.withdraw();
  for (const runtime::Offer& offer : draw.inputs) {
    PENUMBRA_TRY_ASSIGN(Held * held, find(offer.texture, draw.where));
    if (held->mip) {
      inputs_.set(offer.as, held->mip->chain.get(), *held->mip->format, "the min-max mip");
    } else if (held->image) {
      inputs_.give(offer.as, *held->image, held->depth);
    } else {
      inputs_.set(offer.as, held->target.get(), *held->format, held->origin);
    }
  }
  return {};
}

Result<runtime::Drawn> GlDevice::draw(const runtime::Draw& draw) {
  if (draw.pass == PassKind::depth) {
    return make_error(Error::Kind::bad_input, draw.where,
                      "the OpenGL runtime draws no depth pass; give it the map as an image");
  }
  const PassProgram& pass = program(draw.program);
  PENUMBRA_TRY(offer(draw));
  const std::string what = "the " + pass.where;
  PENUMBRA_TRY_ASSIGN(Texture target,
                      create_pass_target(pass, draw.width, draw.height, "the target of " + what));
  if (draw.triangles.empty()) {
    PENUMBRA_TRY(draw_full_screen(pass, draw.params, inputs_,
                                  {target, draw.width, draw.height, software_}, what));
  } else {
    PENUMBRA_TRY(draw_triangles(pass, draw.params, inputs_, draw.triangles,
                                {target, draw.width, draw.height}));
  }
  Held held;
  held.target = std::move(target);
  held.format = pass.target_format;
  held.origin = "the " + pass.where + "'s target";
  return runtime::Drawn{hold(std::move(held), draw.width, draw.height), std::nullopt};
}

Result<runtime::Texture> GlDevice::gather_mip(runtime::Texture map,
                                              std::span<const runtime::Texture> levels) {
  std::vector<const Texture*> targets;
  const TexelFormat* format = nullptr;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    PENUMBRA_TRY_ASSIGN(Held * level, find(levels[l], "the min-max mip"));
    if (format && level->format != format) {
      return make_error(Error::Kind::bad_input, "minmax_reduce pass",
                        "its render target is " + std::string(level->format->name()) +
                            " but the minmax_init pass's is " + std::string(format->name()) +
                            "; both draw levels of one mip");
    }
    format = level->format;
    targets.push_back(&level->target);
  }
  PENUMBRA_TRY_ASSIGN(MinmaxMip mip, gather_minmax_mip(targets, *format, {map.width, map.height}));
  Held held;
  held.mip = std::move(mip);
  return hold(std::move(held), levels.front().width, levels.front().height);
}

Result<std::vector<FloatImage>> GlDevice::read_all(std::span<const runtime::Texture> textures) {
  std::vector<FloatImage> images;
  for (runtime::Texture texture : textures) {
    PENUMBRA_TRY_ASSIGN(FloatImage image, read_one(texture));
    images.push_back(std::move(image));
  }
  return images;
}

Result<FloatImage> GlDevice::read_one(runtime::Texture texture) {
  PENUMBRA_TRY_ASSIGN(Held * held, find(texture, "readback"));
  if (held->image) return *held->image;
  if (held->mip) {
    PENUMBRA_TRY_ASSIGN(std::vector<FloatImage> levels, read_minmax_mip(*held->mip));
    return std::move(levels.front());
  }
  return read_texture(held->target, *held->format, 0, texture.width, texture.height, held->origin);
}

void GlDevice::release(runtime::Texture texture) {
  const auto found = textures_.find(texture.id);
  if (found == textures_.end()) return;
  if (found->second.image) inputs_.forget(*found->second.image);
  textures_.erase(found);
}

}  // namespace penumbra::gl
