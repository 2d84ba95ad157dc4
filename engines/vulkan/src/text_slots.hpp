// Where an entry of a target's reflection lands in the SPIR-V the runtime
// executes for that target's text, by the rules of the target's API
// (docs/runtime.md, "Binding by reflection"): spirv and glsl450 by set and
// binding, Direct3D by register, glsl330 and essl300 by name, as
// glGetUniformLocation looks a name up in the linked program.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra::detail {

// One descriptor the executed module declares: what a driver sees.
struct ModuleResource {
  std::string name;  // as the module names it: "shadow_cmp", "$Global", "_receivers_sampler"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  // sampler2DShadow, a Texture2D read with SampleCmp, or a sampler used with one.
  bool comparison = false;
  const UniformBlock* block = nullptr;  // a uniform buffer's block
};

// "uniform block 'ShadowParams' (set 0 binding 0)": for messages.
std::string describe(const ModuleResource& resource);

// Every descriptor of one stage's module, blocks first.
std::vector<ModuleResource> module_resources(const ShaderInterface& iface);

// One stage's lookups. Each returns an index into `resources` or, when the
// module has nothing there, an empty optional; what was looked for is
// written by the matching where_*() for messages.
class TextSlots {
 public:
  TextSlots(Target target, const std::vector<ModuleResource>& resources)
      : dialect_(traits(target).dialect), resources_(resources) {}

  // The image (combined or separate) of a texture.
  std::optional<std::size_t> texture(const TextureBinding& texture) const;
  // Direct3D 10's separate sampler of a texture (its s# register).
  std::optional<std::size_t> sampler(const TextureBinding& texture) const;
  std::optional<std::size_t> block(const BlockBinding& block) const;
  // A loose uniform (glsl330's struct members, hlsl_dx9's constant
  // registers): the block glslang gathers them into.
  std::optional<std::size_t> uniform_block() const;
  // A loose uniform's offset in uniform_block(): by name (glsl330) or 16
  // bytes per c# register (hlsl_dx9); empty when the block has no member
  // there.
  std::optional<std::uint32_t> uniform_offset(const ConstantBinding& uniform) const;
  // A block member's offset: the reflection's, checked against the member
  // the module has by name (essl300) or at that offset (every other target).
  std::optional<std::uint32_t> member_offset(const BlockBinding& block, std::size_t resource,
                                             const ConstantBinding& member) const;

  std::string where_texture(const TextureBinding& texture) const;
  std::string where_sampler(const TextureBinding& texture) const;
  std::string where_block(const BlockBinding& block) const;

 private:
  std::optional<std::size_t> at(std::uint32_t set, std::uint32_t binding,
                                std::initializer_list<VkDescriptorType> types) const;
  std::optional<std::size_t> named(const std::string& name, VkDescriptorType type) const;

  ReflectionDialect dialect_;
  const std::vector<ModuleResource>& resources_;
};

}  // namespace penumbra::detail
