#include "reflection_binding.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <utility>

#include "formats.hpp"
#include "register_slots.hpp"
#include "text_slots.hpp"

namespace penumbra::detail {
namespace {

bool same_resource(const PlannedBinding& a, const PlannedBinding& b) {
  return a.type == b.type && a.texture == b.texture && a.format == b.format &&
         a.contents == b.contents && a.sampler.has_value() == b.sampler.has_value() &&
         (!a.sampler || *a.sampler == *b.sampler);
}

bool overlaps(const ConstantFill& a, const ConstantFill& b) {
  return a.offset < b.offset + b.size && b.offset < a.offset + a.size;
}

// Accumulates both stages. One binding in both stages is one descriptor:
// the same texture or sampler, or one buffer holding both stages' constants.
class Planner {
 public:
  Planner(const PassProgram& program, std::string_view pass) : program_(program), pass_(pass) {}

  Status add_stage(const StageBindings& bindings, const ShaderInterface& iface,
                   VkShaderStageFlags flag) {
    stage_ = iface.stage == ShaderStage::vertex ? "vertex stage" : "fragment stage";
    flag_ = flag;
    resources_ = module_resources(iface);
    accounted_.assign(resources_.size(), false);
    // Translated bytecode names its resources by register; text as its API finds them.
    const std::unique_ptr<TextSlots> slots =
        program_.d3d_bytecode ? std::make_unique<RegisterSlots>(program_.target, resources_)
                              : std::make_unique<TextSlots>(program_.target, resources_);
    source_ = slots->source();
    for (const TextureBinding& texture : bindings.textures) {
      PENUMBRA_TRY(add_texture(*slots, texture));
    }
    for (const BlockBinding& block : bindings.blocks) PENUMBRA_TRY(add_block(*slots, block));
    if (!bindings.uniforms.empty()) PENUMBRA_TRY(add_uniforms(*slots, bindings.uniforms));
    for (std::size_t i = 0; i < resources_.size(); ++i) {
      if (!accounted_[i]) {
        return fail(source_ + " declares " + describe(resources_[i]) + " (" + stage_ +
                    ") that index.json's reflection lacks");
      }
    }
    return {};
  }

  BindingPlan finish() && {
    BindingPlan plan;
    for (auto& [slot, binding] : slots_) {
      plan.set_count = std::max(plan.set_count, slot.first + 1);
      plan.bindings.push_back(std::move(binding));
    }
    return plan;
  }

 private:
  Error fail(std::string message) const {
    return make_error(Error::Kind::bad_input, std::string(pass_), std::move(message));
  }

  std::string lacking(const std::string& what, const std::string& where) const {
    return "index.json's reflection names " + what + " at " + where + " (" + stage_ + "), which " +
           source_ + " does not declare";
  }

  // A sampler must compare exactly when the module samples with comparisons.
  Status check_comparison(const TextureBinding& texture, const ModuleResource& resource) const {
    if (resource.comparison == texture.sampler.state.comparison) return {};
    return fail("texture '" + texture.name + "': " + source_ + " samples it " +
                (resource.comparison ? "with" : "without") + " comparisons (" + describe(resource) +
                ", " + stage_ + "), but index.json's reflection gives it " +
                (texture.sampler.state.comparison ? "a comparison sampler"
                                                  : "a sampler without comparison"));
  }

  // A constant texture comes with exactly its texels; no other texture does.
  Status check_contents(const TextureBinding& texture, const TextureDescription& described,
                        TextureFormat format) const {
    if (!described.constant) {
      if (!texture.contents) return {};
      return fail("index.json's reflection gives texture '" + texture.name +
                  "' contents, but the engine supplies it every frame");
    }
    if (!texture.contents) {
      return fail("index.json's reflection gives constant texture '" + texture.name +
                  "' no contents");
    }
    const TextureContents& contents = *texture.contents;
    const std::size_t expected =
        std::size_t{contents.width} * contents.height * texel_components(format);
    if (contents.texels.size() != expected) {
      return fail("texture '" + texture.name + "': its contents hold " +
                  std::to_string(contents.texels.size()) + " floats, where " +
                  std::to_string(contents.width) + " x " + std::to_string(contents.height) +
                  " texels of " + texture.format + " need " + std::to_string(expected));
    }
    return {};
  }

  Status add_texture(const TextSlots& slots, const TextureBinding& texture) {
    const TextureDescription* described = find_bound_texture(texture.name);
    if (!described) {
      return fail("index.json's reflection names texture '" + texture.name + "' (" + stage_ +
                  "), which is not a texture of the shader contract");
    }
    TextureFormat format{};
    PENUMBRA_TRY_ASSIGN(format, reflected_format(program_.target, texture.format, pass_));
    const auto image = slots.texture(texture);
    if (!image)
      return fail(lacking("texture '" + texture.name + "'", slots.where_texture(texture)));
    accounted_[*image] = true;
    const ModuleResource& resource = resources_[*image];
    if (slots.images_tell_comparison()) PENUMBRA_TRY(check_comparison(texture, resource));
    PENUMBRA_TRY(check_contents(texture, *described, format));
    PlannedBinding planned{texture.name,
                           resource.set,
                           resource.binding,
                           resource.type,
                           flag_,
                           described,
                           format,
                           texture.contents,
                           std::nullopt,
                           0,
                           {}};
    if (resource.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER) {
      planned.sampler = texture.sampler.state;
    } else if (resource.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE) {
      PENUMBRA_TRY(add_sampler(slots, texture));
    }
    return merge(std::move(planned));
  }

  // A separate image's own sampler object (the d3d10 dialect; any translated bytecode).
  Status add_sampler(const TextSlots& slots, const TextureBinding& texture) {
    const auto sampler = slots.sampler(texture);
    if (!sampler) {
      return fail(
          lacking("sampler '" + texture.sampler.name + "' of texture '" + texture.name + "'",
                  slots.where_sampler(texture)));
    }
    accounted_[*sampler] = true;
    const ModuleResource& resource = resources_[*sampler];
    PENUMBRA_TRY(check_comparison(texture, resource));
    // Direct3D 9's sampler2D has no sampler object of its own to name.
    return merge({texture.sampler.name.empty() ? texture.name + "'s sampler" : texture.sampler.name,
                  resource.set,
                  resource.binding,
                  resource.type,
                  flag_,
                  nullptr,
                  TextureFormat{},
                  std::nullopt,
                  texture.sampler.state,
                  0,
                  {}});
  }

  PlannedBinding buffer(const std::string& name, const ModuleResource& resource) const {
    PlannedBinding planned;
    planned.name = name;
    planned.set = resource.set;
    planned.binding = resource.binding;
    planned.type = resource.type;
    planned.stages = flag_;
    return planned;
  }

  Status add_block(const TextSlots& slots, const BlockBinding& block) {
    const auto index = slots.block(block);
    if (!index)
      return fail(lacking("uniform block '" + block.name + "'", slots.where_block(block)));
    accounted_[*index] = true;
    const ModuleResource& resource = resources_[*index];
    PlannedBinding planned = buffer(block.name, resource);
    planned.size = std::max(block.size, resource.block->size);
    for (const ConstantBinding& member : block.members) {
      const auto offset = slots.member_offset(block, *index, member);
      if (!offset) {
        return fail("index.json's reflection puts '" + member.name + "' at offset " +
                    std::to_string(member.offset.value_or(0)) + " of uniform block '" + block.name +
                    "' (" + stage_ + "), where the text's block has no member of " +
                    std::to_string(member.size) + " bytes");
      }
      planned.constants.push_back({member.name, member.parameter, *offset, member.size});
    }
    PENUMBRA_TRY(check_members(slots, resource, planned.constants));
    return merge(std::move(planned));
  }

  // Loose uniforms, set one by one through the API (glUniform4fv at the
  // name's location, SetPixelShaderConstantF at the register): where the
  // module keeps them, in the block glslang gathers them into.
  Status add_uniforms(const TextSlots& slots, const std::vector<ConstantBinding>& uniforms) {
    const auto index = slots.uniform_block();
    if (!index) return fail(lacking("uniform '" + uniforms[0].name + "'", "its location"));
    accounted_[*index] = true;
    const ModuleResource& resource = resources_[*index];
    PlannedBinding planned = buffer(resource.name, resource);
    planned.size = resource.block->size;
    for (const ConstantBinding& uniform : uniforms) {
      const auto offset = slots.uniform_offset(uniform);
      if (!offset) {
        return fail(lacking("uniform '" + uniform.name + "'",
                            uniform.reg.empty() ? "its location" : "register " + uniform.reg));
      }
      planned.constants.push_back({uniform.name, uniform.parameter, *offset, uniform.size});
      planned.size = std::max(planned.size, *offset + uniform.size);
    }
    PENUMBRA_TRY(check_members(slots, resource, planned.constants));
    return merge(std::move(planned));
  }

  // Every member the module declares is one the reflection fills.
  Status check_members(const TextSlots& slots, const ModuleResource& resource,
                       const std::vector<ConstantFill>& constants) const {
    if (const auto member = slots.unfilled(resource, constants)) {
      return fail(source_ + " declares '" + *member + "' in " + describe(resource) + " (" + stage_ +
                  ") that index.json's reflection lacks");
    }
    return {};
  }

  Status merge(PlannedBinding planned) {
    const std::pair slot{planned.set, planned.binding};
    auto [it, inserted] = slots_.try_emplace(slot, planned);
    if (inserted) return {};
    PlannedBinding& have = it->second;
    if (!same_resource(have, planned)) {
      return fail("'" + have.name + "' and '" + planned.name + "' share set " +
                  std::to_string(slot.first) + " binding " + std::to_string(slot.second));
    }
    have.stages |= planned.stages;
    have.size = std::max(have.size, planned.size);
    for (ConstantFill& constant : planned.constants) {
      const auto clash = std::find_if(have.constants.begin(), have.constants.end(),
                                      [&](const ConstantFill& c) { return overlaps(c, constant); });
      if (clash == have.constants.end()) {
        have.constants.push_back(std::move(constant));
      } else if (clash->offset != constant.offset || clash->size != constant.size ||
                 clash->parameter != constant.parameter) {
        return fail("'" + clash->name + "' and '" + constant.name + "' overlap in '" + have.name +
                    "' at set " + std::to_string(slot.first) + " binding " +
                    std::to_string(slot.second) + ", which both stages share");
      }
    }
    return {};
  }

  const PassProgram& program_;
  std::string_view pass_;
  std::string stage_;
  std::string source_;  // "the text" or "the bytecode", for messages
  VkShaderStageFlags flag_ = 0;
  std::vector<ModuleResource> resources_;
  std::vector<bool> accounted_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, PlannedBinding> slots_;
};

bool lists(const StageBindings& stage, std::string_view name) {
  return std::any_of(stage.textures.begin(), stage.textures.end(),
                     [&](const TextureBinding& t) { return t.name == name; });
}

}  // namespace

Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass) {
  Planner planner(program, pass);
  PENUMBRA_TRY(
      planner.add_stage(program.reflection.vert, program.vert.iface, VK_SHADER_STAGE_VERTEX_BIT));
  PENUMBRA_TRY(
      planner.add_stage(program.reflection.frag, program.frag.iface, VK_SHADER_STAGE_FRAGMENT_BIT));
  return std::move(planner).finish();
}

bool reads_texture(const PassReflection& reflection, TextureId texture) {
  const std::string_view name = describe(texture).name;
  return lists(reflection.vert, name) || lists(reflection.frag, name);
}

}  // namespace penumbra::detail
