// Where an entry of a Direct3D target's reflection lands in the SPIR-V that
// vkd3d-compiler translates the target's bytecode to (docs/runtime.md,
// "Binding by reflection"): every resource is named by its register, in set
// 0 at a binding of vkd3d's choosing (its declaration order).
//
// | reflection                    | translated module                          |
// |-------------------------------|--------------------------------------------|
// | texture t# (Direct3D 10+)     | image `t#`, its sampler s# a sampler `s#`  |
// | sampler2D s# (Direct3D 9)     | image `t#` and sampler `s#`, same number   |
// | constant buffer b#            | uniform buffer `cb<id>_#`: one vec4[N]     |
// | constants c# (Direct3D 9)     | uniform buffer 0, one vec4[N]: c0 to cN-1  |
//
// N is one past the highest register the bytecode reads.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "text_slots.hpp"

namespace penumbra::detail {

class RegisterSlots final : public TextSlots {
 public:
  RegisterSlots(Target target, const std::vector<ModuleResource>& resources)
      : TextSlots(target, resources) {}

  std::optional<std::size_t> texture(const TextureBinding& texture) const override;
  std::optional<std::size_t> sampler(const TextureBinding& texture) const override;
  std::optional<std::size_t> block(const BlockBinding& block) const override;
  std::optional<std::size_t> uniform_block() const override;
  std::optional<std::uint32_t> uniform_offset(const ConstantBinding& uniform) const override;
  std::optional<std::uint32_t> member_offset(const BlockBinding& block, std::size_t resource,
                                             const ConstantBinding& member) const override;
  std::optional<std::string> unfilled(const ModuleResource& buffer,
                                      const std::vector<ConstantFill>& constants) const override;
  // vkd3d declares every image with unknown depth: the sampler a depth
  // comparison reads through tells.
  bool images_tell_comparison() const override { return false; }
  std::string_view source() const override { return "the bytecode"; }

 private:
  std::optional<std::size_t> constant_buffer(std::uint32_t reg) const;
};

}  // namespace penumbra::detail
