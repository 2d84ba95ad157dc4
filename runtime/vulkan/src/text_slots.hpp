// Where an entry of a target's reflection lands in the SPIR-V the runtime
// executes for that target's text, by the rules of the target's API
// (docs/runtime.md, "Binding by reflection"): spirv and glsl450 by set and
// binding, Direct3D by register, glsl330 and essl300 by name, as
// glGetUniformLocation looks a name up in the linked program.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/target_reflection.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "reflection_binding.hpp"

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
// written by the matching where_*() for messages. RegisterSlots
// (register_slots.hpp) looks up by register instead, in translated bytecode.
class TextSlots {
 public:
  TextSlots(Target target, const std::vector<ModuleResource>& resources)
      : dialect_(traits(target).dialect), resources_(resources) {}
  virtual ~TextSlots() = default;

  // The image (combined or separate) of a texture.
  virtual std::optional<std::size_t> texture(const TextureBinding& texture) const;
  // The separate sampler of a texture (the d3d10 dialect's s# register).
  virtual std::optional<std::size_t> sampler(const TextureBinding& texture) const;
  virtual std::optional<std::size_t> block(const BlockBinding& block) const;
  // A loose uniform (glsl330's struct members, hlsl_dx9's constant
  // registers): the block glslang gathers them into.
  virtual std::optional<std::size_t> uniform_block() const;
  // A loose uniform's offset in uniform_block(): by name (glsl330) or 16
  // bytes per c# register (hlsl_dx9); empty when the block has no member
  // there.
  virtual std::optional<std::uint32_t> uniform_offset(const ConstantBinding& uniform) const;
  // A block member's offset: the reflection's, checked against the member
  // the module has by name (essl300) or at that offset (every other target).
  virtual std::optional<std::uint32_t> member_offset(const BlockBinding& block,
                                                     std::size_t resource,
                                                     const ConstantBinding& member) const;
  // The first member of a uniform buffer that no constant fills, or none.
  virtual std::optional<std::string> unfilled(const ModuleResource& buffer,
                                              const std::vector<ConstantFill>& constants) const;
  // Whether an image's type says if it is sampled with comparisons (else
  // only its sampler does).
  virtual bool images_tell_comparison() const { return true; }
  // What the module was made from, for messages: "the text".
  virtual std::string_view source() const { return "the text"; }

  std::string where_texture(const TextureBinding& texture) const;
  std::string where_sampler(const TextureBinding& texture) const;
  std::string where_block(const BlockBinding& block) const;

 protected:
  std::optional<std::size_t> at(std::uint32_t set, std::uint32_t binding,
                                std::initializer_list<VkDescriptorType> types) const;
  std::optional<std::size_t> named(const std::string& name, VkDescriptorType type) const;

  ReflectionDialect dialect_;
  const std::vector<ModuleResource>& resources_;
};

// The number of a register written as HLSL writes it ("t2" with kind 't').
std::optional<std::uint32_t> register_number(std::string_view reg, char kind);

}  // namespace penumbra::detail
