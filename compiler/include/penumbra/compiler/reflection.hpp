// Reflection of one SPIR-V shader stage: what it binds and what it passes.
// The runtime binds resources by these records, never by slot numbers.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra {

enum class ShaderStage { vertex, fragment };

struct BlockMember {
  std::string name;  // e.g. "shadow_map_size"
  std::uint32_t offset = 0;
  std::uint32_t size = 0;  // bytes
};

struct UniformBlock {
  std::string type_name;      // e.g. "ShadowParams"
  std::string instance_name;  // e.g. "params"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  std::uint32_t size = 0;  // declared size in bytes
  std::vector<BlockMember> members;
};

struct SampledImage {
  std::string name;  // e.g. "shadow_cmp"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  bool comparison = false;  // sampler2DShadow
};

struct StageVariable {
  std::string name;
  std::uint32_t location = 0;
  std::uint32_t components = 1;  // vector width of a float vector
};

struct ShaderInterface {
  ShaderStage stage = ShaderStage::vertex;
  std::string entry_point = "main";
  std::vector<UniformBlock> uniform_blocks;
  std::vector<SampledImage> sampled_images;
  std::vector<StageVariable> inputs;
  std::vector<StageVariable> outputs;
};

// Reflects a SPIR-V module with SPIRV-Cross.
Result<ShaderInterface> reflect(std::span<const std::uint32_t> spirv);

void to_json(nlohmann::json& j, const ShaderInterface& iface);
void from_json(const nlohmann::json& j, ShaderInterface& iface);

}  // namespace penumbra
