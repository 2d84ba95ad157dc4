// Proves the spirv target's reflection by SPIRV-Cross's reflection of the
// emitted .spv files: each stage's uniform blocks (set, binding, declared
// size, member names, offsets and types), combined image samplers (set,
// binding, sampler2D or sampler2DShadow, which is the comparison sampler,
// or their array twins),
// the vertex stage's inputs (location, components, Vulkan format) and the
// fragment stage's outputs (location). SPIRV-Cross lists everything the
// module declares, used or not, so both directions are exact.
#include <cstring>
#include <spirv_cross/spirv_cross.hpp>

#include "proof.hpp"

namespace penumbra::testing {
namespace {

// SPIRV-Cross states sets and member sizes too.
constexpr FactStyle kStyle{.with_set = true, .member_sizes = true, .unset_binding = {}};

constexpr std::string_view kVulkanFloats[] = {"VK_FORMAT_R32_SFLOAT", "VK_FORMAT_R32G32_SFLOAT",
                                              "VK_FORMAT_R32G32B32_SFLOAT",
                                              "VK_FORMAT_R32G32B32A32_SFLOAT"};

// "vec4" for a float vector, else SPIRV-Cross's base type number.
std::string value_type(const spirv_cross::SPIRType& type) {
  if (type.basetype == spirv_cross::SPIRType::Float && type.columns == 1) {
    return type.vecsize == 1 ? "float" : "vec" + std::to_string(type.vecsize);
  }
  return "type " + std::to_string(static_cast<int>(type.basetype));
}

void observed_stage(std::string_view stage, const std::string& bytes, Facts& facts) {
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  const spirv_cross::Compiler module(std::move(words));
  const spirv_cross::ShaderResources resources = module.get_shader_resources();
  auto binding = [&](spirv_cross::ID id) {
    return slot_text(kStyle, module.get_decoration(id, spv::DecorationDescriptorSet),
                     module.get_decoration(id, spv::DecorationBinding));
  };
  for (const spirv_cross::Resource& block : resources.uniform_buffers) {
    const spirv_cross::SPIRType& type = module.get_type(block.base_type_id);
    const std::string name = module.get_name(block.base_type_id);
    const std::string key = std::string(stage) + " block " + name;
    facts[key] =
        binding(block.id) + ", " + std::to_string(module.get_declared_struct_size(type)) + " bytes";
    for (std::uint32_t i = 0; i < type.member_types.size(); ++i) {
      facts[key + " member " + module.get_member_name(block.base_type_id, i)] =
          member_text(kStyle, value_type(module.get_type(type.member_types[i])),
                      module.type_struct_member_offset(type, i),
                      static_cast<std::uint32_t>(module.get_declared_struct_member_size(type, i)));
    }
  }
  for (const spirv_cross::Resource& image : resources.sampled_images) {
    const bool depth = module.get_type(image.type_id).image.depth;
    const bool array = module.get_type(image.type_id).image.arrayed;
    facts[std::string(stage) + " texture " + image.name] =
        binding(image.id) + ", " +
        texture_text(std::string(array ? "sampler2DArray" : "sampler2D") + (depth ? "Shadow" : ""),
                     depth);
  }
  // Anything else the module binds has no place in the reflection.
  for (const auto* other :
       {&resources.storage_buffers, &resources.separate_images, &resources.separate_samplers,
        &resources.storage_images, &resources.push_constant_buffers}) {
    for (const spirv_cross::Resource& resource : *other) {
      facts[std::string(stage) + " resource " + resource.name] = binding(resource.id);
    }
  }
  if (stage == "vert") {
    for (const spirv_cross::Resource& input : resources.stage_inputs) {
      const spirv_cross::SPIRType& type = module.get_type(input.type_id);
      const bool floats = type.basetype == spirv_cross::SPIRType::Float && type.vecsize <= 4;
      facts["vert input " + input.name] =
          input_text(module.get_decoration(input.id, spv::DecorationLocation), type.vecsize,
                     floats ? kVulkanFloats[type.vecsize - 1] : "not float");
    }
  } else {
    for (const spirv_cross::Resource& output : resources.stage_outputs) {
      facts["frag output " + output.name] =
          "location " + std::to_string(module.get_decoration(output.id, spv::DecorationLocation));
    }
  }
}

}  // namespace

Status prove_spirv(const Library& library, const LibraryVariant& variant, PassKind pass,
                   Target target) {
  PENUMBRA_TRY_ASSIGN(const PassReflection* reflection, reflection_of(variant, pass, target));
  Facts observed;
  for (const ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
    PENUMBRA_TRY_ASSIGN(const std::string bytes,
                        read_pass_file(library, variant, pass, target, stage));
    try {
      observed_stage(stage_key(stage), bytes, observed);
    } catch (const spirv_cross::CompilerError& error) {
      return proof_error(variant, pass, target,
                         "SPIRV-Cross cannot read the " + std::string(stage_key(stage)) +
                             " module: " + error.what());
    }
  }
  return compare_facts(variant, pass, target, "SPIRV-Cross", reflected_facts(*reflection, kStyle),
                       observed);
}

}  // namespace penumbra::testing
