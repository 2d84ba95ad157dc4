// Resolving a program's reflected resources to what the runtime binds there
// (docs/shader-interface.md, "Resources"), for both stages together.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/runtime/program.hpp"

namespace penumbra::detail {

// The interface's resource names.
inline constexpr std::string_view kParamsBlock = "ShadowParams";
inline constexpr std::string_view kShadowDepth = "shadow_depth";
inline constexpr std::string_view kShadowCmp = "shadow_cmp";
inline constexpr std::string_view kReceivers = "receivers";

enum class BindingRole {
  params,          // ShadowParams: a uniform buffer filled from the ParamBlock
  map_depth,       // shadow_depth: the map's depth image, nearest sampler
  map_colour,      // shadow_depth in a program without shadow_cmp: the R32F image, nearest
  map_comparison,  // shadow_cmp: the map's depth image, comparison sampler
  receivers,       // receivers: the RGBA32F receivers image, nearest sampler
};

struct PlannedBinding {
  std::string name;
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  BindingRole role = BindingRole::params;
  VkShaderStageFlags stages = 0;  // every stage that declares it
};

// ShadowParams as both stages declare it: the union of their members.
struct ParamsLayout {
  std::uint32_t size = 0;
  std::vector<BlockMember> members;
};

struct BindingPlan {
  std::vector<PlannedBinding> bindings;  // ordered by set, then binding
  ParamsLayout params;                   // empty unless a params binding exists
  std::uint32_t set_count = 0;           // the highest set used + 1
};

// `available`: the interface names this pass has something to bind to.
// Errors (bad_input, where = `pass`) name the offending resource: a name the
// interface does not have, one the pass cannot bind, a sampler of the wrong
// kind, or two resources sharing one binding.
Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass,
                                  std::span<const std::string_view> available);

}  // namespace penumbra::detail
