#include <algorithm>
#include <set>
#include <string>
#include <tuple>

#include "penumbra/spirv/module.hpp"
#include "reflect_parts.hpp"

namespace penumbra {

std::string paired_image_name(std::string_view sampler_name) {
  constexpr std::string_view prefix = "_";
  constexpr std::string_view suffix = "_sampler";
  if (sampler_name.size() <= prefix.size() + suffix.size() || !sampler_name.starts_with(prefix) ||
      !sampler_name.ends_with(suffix)) {
    return "";
  }
  return std::string(
      sampler_name.substr(prefix.size(), sampler_name.size() - prefix.size() - suffix.size()));
}

namespace detail {
namespace {

using spirv_cross::Compiler;
using spirv_cross::Resource;

std::uint32_t set_of(const Compiler& compiler, const Resource& resource) {
  return compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
}

std::uint32_t binding_of(const Compiler& compiler, const Resource& resource) {
  return compiler.get_decoration(resource.id, spv::DecorationBinding);
}

template <typename Record>
void sort_by_slot(std::vector<Record>& records) {
  std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
    return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
  });
}

// SPIR-V samplers have no comparison flag; what tells is their use. SPIRV-Cross
// pairs every image with the samplers that sample it (as it does to emit
// GLSL's combined samplers) and gives a pair a depth type when its image is
// a depth image, which glslang makes of images compared through a sampler.
std::set<std::uint32_t> comparison_sampler_ids(Compiler& compiler) {
  compiler.build_combined_image_samplers();
  std::set<std::uint32_t> ids;
  for (const spirv_cross::CombinedImageSampler& pair : compiler.get_combined_image_samplers()) {
    if (compiler.get_type_from_variable(pair.combined_id).image.depth) ids.insert(pair.sampler_id);
  }
  return ids;
}

bool compares(spv::Op op) {
  switch (op) {
    case spv::OpImageSampleDrefImplicitLod:
    case spv::OpImageSampleDrefExplicitLod:
    case spv::OpImageSampleProjDrefImplicitLod:
    case spv::OpImageSampleProjDrefExplicitLod:
    case spv::OpImageDrefGather:
      return true;
    default:
      return false;
  }
}

// The sampler variables that depth comparisons sample through: what tells
// a comparison sampler where no image says Depth = 1 (vkd3d-compiler's
// translations declare every image with unknown depth).
std::set<std::uint32_t> compared_sampler_variables(std::span<const std::uint32_t> spirv) {
  const SpirvModule module(spirv);
  std::set<std::uint32_t> out;
  for (const SpvInstruction& instruction : module.instructions()) {
    if (!compares(instruction.op)) continue;
    const SpvInstruction* combined = module.def(instruction.operand(0));
    if (!combined || combined->op != spv::OpSampledImage) continue;
    const SpvInstruction* sampler = module.def(combined->operand(1));
    if (sampler && sampler->op == spv::OpLoad) out.insert(sampler->operand(0));
  }
  return out;
}

}  // namespace

void reflect_images(Compiler& compiler, const spirv_cross::ShaderResources& resources,
                    std::span<const std::uint32_t> spirv, ShaderInterface& iface) {
  for (const Resource& resource : resources.sampled_images) {
    const spirv_cross::SPIRType::ImageType& image = compiler.get_type(resource.type_id).image;
    iface.sampled_images.push_back({resource.name, set_of(compiler, resource),
                                    binding_of(compiler, resource), image.depth, image.arrayed});
  }
  for (const Resource& resource : resources.separate_images) {
    const spirv_cross::SPIRType::ImageType& image = compiler.get_type(resource.type_id).image;
    iface.separate_images.push_back({resource.name, set_of(compiler, resource),
                                     binding_of(compiler, resource), image.depth, image.arrayed});
  }
  const auto comparison = resources.separate_samplers.empty() ? std::set<std::uint32_t>()
                                                              : comparison_sampler_ids(compiler);
  const auto compared = resources.separate_samplers.empty() ? std::set<std::uint32_t>()
                                                            : compared_sampler_variables(spirv);
  for (const Resource& resource : resources.separate_samplers) {
    iface.separate_samplers.push_back(
        {resource.name, set_of(compiler, resource), binding_of(compiler, resource),
         paired_image_name(resource.name),
         comparison.contains(resource.id) || compared.contains(resource.id)});
  }
  sort_by_slot(iface.sampled_images);
  sort_by_slot(iface.separate_images);
  sort_by_slot(iface.separate_samplers);
}

}  // namespace detail
}  // namespace penumbra
