// Resolving a program's reflected resources to what the runtime binds there
// (docs/shader-interface.md, "Resources"; docs/runtime.md, "Binding by
// reflection"), for both stages together.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/runtime/program.hpp"

namespace penumbra::detail {

// The interface's resource names.
inline constexpr std::string_view kParamsBlock = "ShadowParams";
inline constexpr std::string_view kShadowDepth = "shadow_depth";
inline constexpr std::string_view kShadowCmp = "shadow_cmp";
inline constexpr std::string_view kReceivers = "receivers";
inline constexpr std::string_view kShadowMinmax = "shadow_minmax";
inline constexpr std::string_view kMinmaxSource = "minmax_source";
inline constexpr std::string_view kScreenFactor = "screen_factor";
inline constexpr std::string_view kSceneColour = "scene_colour";
// glslang's global uniform blocks, holding ShadowParams' members when the
// source declares them outside a block: GLSL's loose uniforms under Vulkan's
// relaxed rules (glslang's default name, or the one compile_target_text
// gives it) and HLSL's globals (the Direct3D 9 constant registers).
inline constexpr std::string_view kGlobalBlocks[] = {"gl_DefaultUniformBlock",
                                                     kLooseUniformBlockName, "$Global"};

enum class BindingRole {
  params,          // ShadowParams: a uniform buffer filled from the ParamBlock
  map_depth,       // shadow_depth: the map's depth image, nearest sampler
  map_colour,      // shadow_depth in a program without shadow_cmp: the R32F image, nearest
  map_comparison,  // shadow_cmp: the map's depth image, comparison sampler
  receivers,       // receivers: the RGBA32F receivers image, nearest sampler
  minmax_mip,      // shadow_minmax: the map's RG32F min-max mip, every level, nearest sampler
  minmax_source,   // minmax_source: the RG32F level a minmax_reduce pass reads, nearest
  screen_factor,   // screen_factor: the RG32F factor a screen_blur pass reads, nearest
  scene_colour,    // scene_colour: the RGBA32F colour the composite pass reads, nearest
};

// A uniform block as every stage declaring it at one binding does: the
// union of their members.
struct ParamsLayout {
  std::string block;  // the block's type name, e.g. "$Global"
  std::uint32_t size = 0;
  std::vector<BlockMember> members;
};

struct PlannedBinding {
  std::string name;  // the first resource reflected here
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  BindingRole role = BindingRole::params;
  // UNIFORM_BUFFER for a block; COMBINED_IMAGE_SAMPLER for a sampler2D, or a
  // separate image and its sampler on one binding; SAMPLED_IMAGE or SAMPLER
  // for a separate image or sampler alone. Images take the role's image,
  // samplers the role's sampler.
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  VkShaderStageFlags stages = 0;  // every stage that declares it
  ParamsLayout params;            // the block, for a params binding
};

struct BindingPlan {
  std::vector<PlannedBinding> bindings;  // ordered by set, then binding
  std::uint32_t set_count = 0;           // the highest set used + 1
};

// `available`: the interface names this pass has something to bind to.
// Errors (bad_input, where = `pass`) name the offending resource: a name the
// interface does not have, one the pass cannot bind, a sampler of the wrong
// kind or pairing with no image, two resources sharing one binding, or block
// members that disagree between the stages.
Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass,
                                  std::span<const std::string_view> available);

}  // namespace penumbra::detail
