// Reflection of one SPIR-V shader stage: what it binds and what it passes.
// The runtime binds resources by these records, never by slot numbers.
//
// It covers the shapes of SPIR-V compiled from Penumbra's shaderlib and from
// the text of every target by glslang (docs/runtime.md, "Binding by
// reflection"): uniform blocks, possibly holding structs (GLSL's loose
// uniforms land in a global block `gl_DefaultUniformBlock`, HLSL's in
// `$Global`); combined image samplers (GLSL sampler2D, Direct3D 9 sampler2D);
// and separate images and samplers (Direct3D 10 Texture2D + SamplerState).
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/pass.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// One leaf of a uniform block. Struct members are flattened: a member
// `params` of struct type ShadowParams yields "params.shadow_map_size",
// "params.light", ... at their absolute offsets in the block.
struct BlockMember {
  std::string name;  // e.g. "shadow_map_size", "params.light", "params_light", "gl_HalfPixel"
  std::uint32_t offset = 0;
  std::uint32_t size = 0;  // bytes
  bool operator==(const BlockMember&) const = default;
};

struct UniformBlock {
  std::string type_name;      // e.g. "ShadowParams", "gl_DefaultUniformBlock", "$Global"
  std::string instance_name;  // e.g. "params"; "" when the block variable has no name
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  std::uint32_t size = 0;  // declared size in bytes
  std::vector<BlockMember> members;
  bool operator==(const UniformBlock&) const = default;
};

// A combined image sampler (OpTypeSampledImage): GLSL sampler2D/sampler2DShadow.
struct SampledImage {
  std::string name;  // e.g. "shadow_cmp"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  bool comparison = false;  // sampler2DShadow (the image type has Depth = 1)
  bool arrayed = false;     // sampler2DArray, sampler2DArrayShadow (Arrayed = 1)
  bool operator==(const SampledImage&) const = default;
};

// A separate sampled image (OpTypeImage, Sampled = 1): HLSL Texture2D.
struct SeparateImage {
  std::string name;  // e.g. "shadow_cmp"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  // Depth = 1: a depth image. glslang's HLSL front end marks a Texture2D so
  // when it is read with SampleCmp.
  bool depth = false;
  bool arrayed = false;  // Texture2DArray (Arrayed = 1)
  bool operator==(const SeparateImage&) const = default;
};

// A separate sampler (OpTypeSampler): HLSL SamplerState or
// SamplerComparisonState, which SPIR-V does not tell apart by type.
struct SeparateSampler {
  std::string name;  // e.g. "_shadow_cmp_sampler"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  std::string image;  // paired_image_name(name): the image it samples by name, or ""
  // Used with a depth image in the module (SPIRV-Cross's analysis of which
  // images each sampler samples) or by a depth comparison (OpImage*Dref*):
  // in practice, a comparison sampler.
  bool comparison = false;
  bool operator==(const SeparateSampler&) const = default;
};

struct StageVariable {
  std::string name;
  std::uint32_t location = 0;
  std::uint32_t components = 1;  // vector width of a float vector
  bool operator==(const StageVariable&) const = default;
};

struct ShaderInterface {
  ShaderStage stage = ShaderStage::vertex;
  std::string entry_point = "main";
  std::vector<UniformBlock> uniform_blocks;
  std::vector<SampledImage> sampled_images;        // ordered by set, then binding
  std::vector<SeparateImage> separate_images;      // ordered by set, then binding
  std::vector<SeparateSampler> separate_samplers;  // ordered by set, then binding
  std::vector<StageVariable> inputs;               // ordered by location
  std::vector<StageVariable> outputs;              // ordered by location
  // Built-in outputs the stage declares, by SPIR-V BuiltIn name: "Position",
  // "PointSize", "ClipDistance", "CullDistance", "FragDepth", ...
  std::vector<std::string> builtin_outputs;
  bool operator==(const ShaderInterface&) const = default;
};

// Reflects a SPIR-V module with SPIRV-Cross.
Result<ShaderInterface> reflect(std::span<const std::uint32_t> spirv);

// The pairing rule for separate samplers, after SPIRV-Cross's HLSL naming:
// it splits a combined sampler2D `x` into `Texture2D x` and a sampler named
// `_x_sampler`. So "_shadow_cmp_sampler" pairs with "shadow_cmp"; a name of
// any other form pairs with nothing ("").
std::string paired_image_name(std::string_view sampler_name);

// The JSON of a ShaderInterface (the library's index.json). from_json accepts
// records written before separate_images, separate_samplers and
// builtin_outputs existed, reading them as empty.
void to_json(nlohmann::json& j, const ShaderInterface& iface);
void from_json(const nlohmann::json& j, ShaderInterface& iface);

}  // namespace penumbra
