#include "text_slots.hpp"

#include <algorithm>
#include <charconv>

#include "penumbra/spirv/text_bindings.hpp"

namespace penumbra::detail {
namespace {

using Dialect = ReflectionDialect;

// glslang's block for HLSL's loose uniforms: Direct3D 9's constant
// registers, register(cN) at offset 16 * N (docs/frontends.md).
constexpr std::string_view kHlslGlobalBlock = "$Global";

std::string slot_text(std::uint32_t set, std::uint32_t binding) {
  return "set " + std::to_string(set) + " binding " + std::to_string(binding);
}

const char* kind_name(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return "uniform block";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
      return "sampler";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
      return "texture";
    default:
      return "sampler object";
  }
}

}  // namespace

std::optional<std::uint32_t> register_number(std::string_view reg, char kind) {
  if (reg.size() < 2 || reg[0] != kind) return std::nullopt;
  std::uint32_t number = 0;
  const auto [end, error] = std::from_chars(reg.data() + 1, reg.data() + reg.size(), number);
  if (error != std::errc() || end != reg.data() + reg.size()) return std::nullopt;
  return number;
}

std::string describe(const ModuleResource& resource) {
  return std::string(kind_name(resource.type)) + " '" + resource.name + "' (" +
         slot_text(resource.set, resource.binding) + ")";
}

std::vector<ModuleResource> module_resources(const ShaderInterface& iface) {
  std::vector<ModuleResource> out;
  for (const UniformBlock& block : iface.uniform_blocks) {
    out.push_back({block.type_name, block.set, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                   false, &block});
  }
  for (const SampledImage& image : iface.sampled_images) {
    out.push_back({image.name, image.set, image.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                   image.comparison, nullptr});
  }
  for (const SeparateImage& image : iface.separate_images) {
    out.push_back({image.name, image.set, image.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
                   image.depth, nullptr});
  }
  for (const SeparateSampler& sampler : iface.separate_samplers) {
    out.push_back({sampler.name, sampler.set, sampler.binding, VK_DESCRIPTOR_TYPE_SAMPLER,
                   sampler.comparison, nullptr});
  }
  return out;
}

std::optional<std::size_t> TextSlots::at(std::uint32_t set, std::uint32_t binding,
                                         std::initializer_list<VkDescriptorType> types) const {
  for (std::size_t i = 0; i < resources_.size(); ++i) {
    const ModuleResource& r = resources_[i];
    if (r.set == set && r.binding == binding &&
        std::find(types.begin(), types.end(), r.type) != types.end()) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> TextSlots::named(const std::string& name, VkDescriptorType type) const {
  for (std::size_t i = 0; i < resources_.size(); ++i) {
    if (resources_[i].name == name && resources_[i].type == type) return i;
  }
  return std::nullopt;
}

std::optional<std::size_t> TextSlots::texture(const TextureBinding& texture) const {
  constexpr VkDescriptorType kCombined = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  switch (dialect_) {
    case Dialect::spirv:
    case Dialect::glsl450:
      if (!texture.binding) return std::nullopt;
      return at(texture.set.value_or(0), *texture.binding,
                {kCombined, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE});
    case Dialect::glsl330:
    case Dialect::essl300:
      return named(texture.name, kCombined);
    case Dialect::d3d10:
      if (auto t = register_number(texture.reg, 't')) {
        return at(0, *t, {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE});
      }
      return std::nullopt;
    case Dialect::d3d9:
      // glslang binds a DX9 sampler2D, texture and sampler in one, at its s#.
      if (auto s = register_number(texture.reg, 's')) return at(0, *s, {kCombined});
      return std::nullopt;
  }
  return std::nullopt;
}

std::optional<std::size_t> TextSlots::sampler(const TextureBinding& texture) const {
  if (dialect_ != Dialect::d3d10) return std::nullopt;
  const auto s = register_number(texture.sampler.reg, 's');
  if (!s) return std::nullopt;
  return at(0, kHlslSamplerBindingBase + *s, {VK_DESCRIPTOR_TYPE_SAMPLER});
}

std::optional<std::size_t> TextSlots::block(const BlockBinding& block) const {
  constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  switch (dialect_) {
    case Dialect::spirv:
    case Dialect::glsl450:
      if (!block.binding) return std::nullopt;
      return at(block.set.value_or(0), *block.binding, {kBuffer});
    case Dialect::d3d10:
      if (auto b = register_number(block.reg, 'b')) return at(0, *b, {kBuffer});
      return std::nullopt;
    case Dialect::glsl330:
    case Dialect::essl300:
    case Dialect::d3d9:
      return named(block.name, kBuffer);
  }
  return std::nullopt;
}

std::optional<std::size_t> TextSlots::uniform_block() const {
  if (dialect_ == Dialect::glsl330) {
    return named(std::string(kLooseUniformBlockName), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  }
  if (dialect_ == Dialect::d3d9) {
    return named(std::string(kHlslGlobalBlock), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  }
  return std::nullopt;
}

std::optional<std::uint32_t> TextSlots::uniform_offset(const ConstantBinding& uniform) const {
  const auto block = uniform_block();
  if (!block) return std::nullopt;
  const std::vector<BlockMember>& members = resources_[*block].block->members;
  const auto found = [&](auto&& match) -> std::optional<std::uint32_t> {
    const auto it = std::find_if(members.begin(), members.end(), match);
    if (it == members.end()) return std::nullopt;
    return it->offset;
  };
  if (dialect_ == Dialect::glsl330) {
    return found([&](const BlockMember& m) { return m.name == uniform.name; });
  }
  const auto c = register_number(uniform.reg, 'c');
  if (!c) return std::nullopt;
  return found([&](const BlockMember& m) { return m.offset == 16 * *c; });
}

std::optional<std::uint32_t> TextSlots::member_offset(const BlockBinding& block,
                                                      std::size_t resource,
                                                      const ConstantBinding& member) const {
  if (!member.offset) return std::nullopt;
  const std::vector<BlockMember>& members = resources_[resource].block->members;
  // ES block members are reported as "<block>.<member>".
  const std::string prefix = block.name + ".";
  const bool by_name = dialect_ == Dialect::essl300;
  const auto it = std::find_if(members.begin(), members.end(), [&](const BlockMember& m) {
    if (!by_name) return m.offset == *member.offset;
    return member.name.starts_with(prefix) && m.name == member.name.substr(prefix.size());
  });
  if (it == members.end() || it->offset != *member.offset || it->size < member.size) {
    return std::nullopt;
  }
  return it->offset;
}

std::optional<std::string> TextSlots::unfilled(const ModuleResource& buffer,
                                               const std::vector<ConstantFill>& constants) const {
  for (const BlockMember& member : buffer.block->members) {
    const bool filled = std::any_of(constants.begin(), constants.end(),
                                    [&](const auto& c) { return c.offset == member.offset; });
    if (!filled) return member.name;
  }
  return std::nullopt;
}

std::string TextSlots::where_texture(const TextureBinding& texture) const {
  switch (dialect_) {
    case Dialect::spirv:
    case Dialect::glsl450:
      return slot_text(texture.set.value_or(0), texture.binding.value_or(0));
    case Dialect::d3d10:
    case Dialect::d3d9:
      return "register " + (texture.reg.empty() ? std::string("(none)") : texture.reg);
    default:
      return "by name";
  }
}

std::string TextSlots::where_sampler(const TextureBinding& texture) const {
  return "register " + (texture.sampler.reg.empty() ? std::string("(none)") : texture.sampler.reg);
}

std::string TextSlots::where_block(const BlockBinding& block) const {
  switch (dialect_) {
    case Dialect::spirv:
    case Dialect::glsl450:
      return slot_text(block.set.value_or(0), block.binding.value_or(0));
    case Dialect::d3d10:
      return "register " + (block.reg.empty() ? std::string("(none)") : block.reg);
    default:
      return "by name";
  }
}

}  // namespace penumbra::detail
