// A pass's descriptors, planned from its reflection record (index.json's
// reflection.<pass>.<target>) as an engine binds them, and checked against
// the descriptors the executed SPIR-V declares (docs/runtime.md, "Binding by
// reflection").
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/shader_contract.hpp"
#include "penumbra/vulkan/program.hpp"

namespace penumbra::detail {

// One ShadowParams member (or the half-pixel constant) the engine writes
// into a uniform buffer.
struct ConstantFill {
  std::string name;       // as the reflection names it: "params.light", "params_light"
  std::string parameter;  // the ParamBlock key, or kHalfPixelParameter
  std::uint32_t offset = 0;
  std::uint32_t size = 0;
};

struct PlannedBinding {
  std::string name;  // the reflection's name for it, for messages
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  // As the module declares it: UNIFORM_BUFFER, COMBINED_IMAGE_SAMPLER,
  // SAMPLED_IMAGE (HLSL Texture2D) or SAMPLER (HLSL SamplerState).
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  VkShaderStageFlags stages = 0;  // every stage that declares it
  // An image: the texture it is (the engine picks the image by its name)
  // and the format the reflection gives it.
  const TextureDescription* texture = nullptr;
  TextureFormat format = TextureFormat::r32_float;
  // A constant texture (TextureDescription::constant): what the engine
  // creates it with, from the reflection.
  std::optional<TextureContents> contents;
  std::optional<SamplerState> sampler;  // a sampler: the state to create it with
  std::uint32_t size = 0;               // a uniform buffer: its bytes
  std::vector<ConstantFill> constants;  // and what fills them
};

struct BindingPlan {
  std::vector<PlannedBinding> bindings;  // ordered by set, then binding
  std::uint32_t set_count = 0;           // the highest set used + 1
};

// Plans every binding from `program.reflection` in `program.target`'s
// terms. Errors (bad_input, where = `pass`) name: a reflection entry the
// module does not declare there, or one outside the shader contract; a
// descriptor of the module the reflection does not account for; a sampler
// state whose comparison disagrees with how the module samples; two stages
// disagreeing on one binding.
Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass);

// True when either stage's reflection lists `texture`.
bool reads_texture(const PassReflection& reflection, TextureId texture);

}  // namespace penumbra::detail
