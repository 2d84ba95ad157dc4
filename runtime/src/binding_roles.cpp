#include "binding_roles.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <span>

namespace penumbra::detail {
namespace {

constexpr std::string_view kImages[] = {kShadowDepth,  kShadowCmp,    kReceivers,  kShadowMinmax,
                                        kMinmaxSource, kScreenFactor, kSceneColour};

const char* stage_name(const ShaderInterface& iface) {
  return iface.stage == ShaderStage::vertex ? "vertex" : "fragment";
}

// The interface's image names; the returned views outlive the reflection.
std::optional<std::string_view> interface_image(std::string_view name) {
  for (std::string_view known : kImages) {
    if (name == known) return known;
  }
  return std::nullopt;
}

bool is_params_block(std::string_view name) {
  return name == kParamsBlock || std::find(std::begin(kGlobalBlocks), std::end(kGlobalBlocks),
                                           name) != std::end(kGlobalBlocks);
}

BindingRole image_role(std::string_view image, bool has_comparison) {
  if (image == kShadowCmp) return BindingRole::map_comparison;
  if (image == kReceivers) return BindingRole::receivers;
  if (image == kShadowMinmax) return BindingRole::minmax_mip;
  if (image == kMinmaxSource) return BindingRole::minmax_source;
  if (image == kScreenFactor) return BindingRole::screen_factor;
  if (image == kSceneColour) return BindingRole::scene_colour;
  return has_comparison ? BindingRole::map_depth : BindingRole::map_colour;
}

// "_shadow_depth_sampler, ...": the separate samplers the interface's images pair with.
std::string sampler_names() {
  std::string text;
  for (std::string_view image : kImages) {
    text += (text.empty() ? "_" : ", _") + std::string(image) + "_sampler";
  }
  return text;
}

class StageResolver {
 public:
  StageResolver(const ShaderInterface& iface, bool has_comparison, std::string_view pass)
      : iface_(iface), has_comparison_(has_comparison), pass_(pass) {}

  Result<std::vector<ResolvedResource>> resolve() const {
    std::vector<ResolvedResource> out;
    for (const UniformBlock& block : iface_.uniform_blocks) {
      if (!is_params_block(block.type_name)) {
        return fail("uniform block '" + block.type_name + "' (" + stage_name(iface_) +
                    " stage) is not part of the shader interface; the only uniform block is " +
                    std::string(kParamsBlock) + ", or a global block of glslang's (" +
                    joined(kGlobalBlocks) + ") holding its members");
      }
      out.push_back({block.type_name, kParamsBlock, block.set, block.binding, BindingRole::params,
                     VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &block});
    }
    for (const SampledImage& image : iface_.sampled_images) {
      auto name = known_image("sampler", image.name);
      if (!name) return name.error();
      const bool is_cmp = *name == kShadowCmp;
      if (image.comparison != is_cmp) {
        return fail(
            "sampler '" + image.name + "' must be a " +
            (is_cmp ? "sampler2DShadow (comparison sampler)" : "sampler2D (no comparison)"));
      }
      out.push_back({image.name, *name, image.set, image.binding, role(*name),
                     VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    }
    for (const SeparateImage& image : iface_.separate_images) {
      auto name = known_image("image", image.name);
      if (!name) return name.error();
      if (image.depth != (*name == kShadowCmp)) {
        return fail("image '" + image.name + "' must be " +
                    (*name == kShadowCmp ? "read with comparisons (SampleCmp)"
                                         : "read without comparisons"));
      }
      out.push_back({image.name, *name, image.set, image.binding, role(*name),
                     VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE});
    }
    for (const SeparateSampler& sampler : iface_.separate_samplers) {
      auto resolved = resolve_sampler(sampler);
      if (!resolved) return resolved.error();
      out.push_back(std::move(*resolved));
    }
    return out;
  }

 private:
  Error fail(std::string message) const {
    return make_error(Error::Kind::bad_input, std::string(pass_), std::move(message));
  }

  BindingRole role(std::string_view image) const { return image_role(image, has_comparison_); }

  Result<std::string_view> known_image(const char* kind, const std::string& name) const {
    if (auto known = interface_image(name)) return *known;
    return fail(std::string(kind) + " '" + name + "' (" + stage_name(iface_) +
                " stage) is not part of the shader interface; allowed names: " + joined(kImages));
  }

  // A separate sampler serves the image its name pairs it with
  // (paired_image_name): the comparison sampler for shadow_cmp, else nearest.
  Result<ResolvedResource> resolve_sampler(const SeparateSampler& sampler) const {
    const auto image = interface_image(sampler.image);
    if (!image) {
      return fail("sampler '" + sampler.name + "' (" + stage_name(iface_) +
                  " stage) pairs with no image of the shader interface: a separate sampler is "
                  "named _<image>_sampler after the image it samples (SPIRV-Cross's HLSL "
                  "naming); allowed names: " +
                  sampler_names());
    }
    if (!sampler.comparison && *image == kShadowCmp) {
      return fail("sampler '" + sampler.name + "' (" + stage_name(iface_) +
                  " stage) must be a comparison sampler (SamplerComparisonState): shadow_cmp "
                  "is only read with comparisons");
    }
    if (sampler.comparison && *image != kShadowCmp) {
      return fail("sampler '" + sampler.name + "' (" + stage_name(iface_) +
                  " stage) samples a depth image for comparisons; only shadow_cmp's sampler, "
                  "_shadow_cmp_sampler, is a comparison sampler");
    }
    return ResolvedResource{sampler.name,    *image,       sampler.set,
                            sampler.binding, role(*image), VK_DESCRIPTOR_TYPE_SAMPLER};
  }

  const ShaderInterface& iface_;
  bool has_comparison_;
  std::string_view pass_;
};

bool stage_declares(const ShaderInterface& iface, std::string_view image_name) {
  const auto named = [image_name](const auto& image) { return image.name == image_name; };
  return std::any_of(iface.sampled_images.begin(), iface.sampled_images.end(), named) ||
         std::any_of(iface.separate_images.begin(), iface.separate_images.end(), named);
}

}  // namespace

std::string joined(std::span<const std::string_view> names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

bool declares_image(const PassProgram& program, std::string_view image_name) {
  return stage_declares(program.vert.iface, image_name) ||
         stage_declares(program.frag.iface, image_name);
}

bool declares_comparison(const PassProgram& program) {
  return declares_image(program, kShadowCmp);
}

Result<std::vector<ResolvedResource>> resolve_stage(const ShaderInterface& iface,
                                                    bool has_comparison, std::string_view pass) {
  return StageResolver(iface, has_comparison, pass).resolve();
}

}  // namespace penumbra::detail
