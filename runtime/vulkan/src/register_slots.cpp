#include "register_slots.hpp"

#include <algorithm>
#include <charconv>

namespace penumbra::detail {
namespace {

constexpr std::uint32_t kRegisterBytes = 16;  // one float4 register

// The register of vkd3d's name for a constant buffer, "cb<id>_<register>"
// (the id is the register itself below shader model 5.1).
std::optional<std::uint32_t> buffer_register(std::string_view name) {
  const std::size_t underscore = name.rfind('_');
  if (!name.starts_with("cb") || underscore == std::string_view::npos) return std::nullopt;
  std::uint32_t number = 0;
  const char* first = name.data() + underscore + 1;
  const char* last = name.data() + name.size();
  const auto [end, error] = std::from_chars(first, last, number);
  if (error != std::errc() || end != last || first == last) return std::nullopt;
  return number;
}

// The register a texture's image or sampler is named by: its own for a
// Direct3D 10+ Texture2D (t#) or SamplerState (s#); a Direct3D 9 sampler2D
// (s#) declares both, which vkd3d names t# and s# of the same number.
std::optional<std::uint32_t> texture_register(const TextureBinding& texture, char kind) {
  if (kind == 's' && !texture.sampler.reg.empty()) return register_number(texture.sampler.reg, 's');
  if (auto own = register_number(texture.reg, kind)) return own;
  return register_number(texture.reg, 's');
}

}  // namespace

std::optional<std::size_t> RegisterSlots::texture(const TextureBinding& texture) const {
  const auto t = texture_register(texture, 't');
  if (!t) return std::nullopt;
  return named("t" + std::to_string(*t), VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
}

std::optional<std::size_t> RegisterSlots::sampler(const TextureBinding& texture) const {
  const auto s = texture_register(texture, 's');
  if (!s) return std::nullopt;
  return named("s" + std::to_string(*s), VK_DESCRIPTOR_TYPE_SAMPLER);
}

std::optional<std::size_t> RegisterSlots::constant_buffer(std::uint32_t reg) const {
  for (std::size_t i = 0; i < resources_.size(); ++i) {
    const ModuleResource& r = resources_[i];
    if (r.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER &&
        buffer_register(r.block->instance_name) == reg) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> RegisterSlots::block(const BlockBinding& block) const {
  const auto b = register_number(block.reg, 'b');
  if (!b) return std::nullopt;
  return constant_buffer(*b);
}

// Direct3D 9's float constants are vkd3d's constant buffer 0.
std::optional<std::size_t> RegisterSlots::uniform_block() const {
  return constant_buffer(0);
}

// The whole constant file is bound, as SetVertexShaderConstantF and
// SetPixelShaderConstantF fill it: registers past the module's array are
// written and not read.
std::optional<std::uint32_t> RegisterSlots::uniform_offset(const ConstantBinding& uniform) const {
  const auto c = register_number(uniform.reg, 'c');
  if (!c) return std::nullopt;
  return kRegisterBytes * *c;
}

// A constant buffer is bound whole; the module's array reads its first N
// registers.
std::optional<std::uint32_t> RegisterSlots::member_offset(const BlockBinding& /*block*/,
                                                          std::size_t /*resource*/,
                                                          const ConstantBinding& member) const {
  return member.offset;
}

// The array's last register, the highest the bytecode reads, is one the
// reflection fills: else the shader reads a constant the engine never sets.
// Registers below it may be ones the bytecode does not read (a vertex shader
// reading c6 alone has c0 to c6), so the record may leave them out.
std::optional<std::string> RegisterSlots::unfilled(
    const ModuleResource& buffer, const std::vector<ConstantFill>& constants) const {
  for (const BlockMember& member : buffer.block->members) {
    const std::uint32_t last = member.offset + member.size - kRegisterBytes;
    const bool filled = std::any_of(constants.begin(), constants.end(), [&](const auto& c) {
      return c.offset <= last && last + kRegisterBytes <= c.offset + c.size;
    });
    if (!filled) {
      return buffer.block->instance_name + "[" + std::to_string(last / kRegisterBytes) + "]";
    }
  }
  return std::nullopt;
}

}  // namespace penumbra::detail
