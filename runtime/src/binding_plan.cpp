#include "binding_plan.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

namespace penumbra::detail {
namespace {

std::string joined(std::span<const std::string_view> names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

std::string slot_name(std::uint32_t set, std::uint32_t binding) {
  return "set " + std::to_string(set) + " binding " + std::to_string(binding);
}

const char* stage_name(const ShaderInterface& iface) {
  return iface.stage == ShaderStage::vertex ? "vertex" : "fragment";
}

// Accumulates both stages' resources, checking each against the interface.
class Planner {
 public:
  Planner(std::string_view pass, std::span<const std::string_view> available, bool has_comparison)
      : pass_(pass), available_(available), has_comparison_(has_comparison) {}

  Status add_stage(const ShaderInterface& iface, VkShaderStageFlags stage) {
    for (const UniformBlock& block : iface.uniform_blocks) {
      if (block.type_name != kParamsBlock) {
        return fail("uniform block '" + block.type_name + "' (" + stage_name(iface) +
                    " stage) is not part of the shader interface; the only uniform block is " +
                    std::string(kParamsBlock));
      }
      PENUMBRA_TRY(add({block.type_name, block.set, block.binding, BindingRole::params, stage}));
      PENUMBRA_TRY(merge_members(block));
    }
    for (const SampledImage& image : iface.sampled_images) {
      auto role = role_of(image, iface);
      if (!role) return role.error();
      PENUMBRA_TRY(add({image.name, image.set, image.binding, *role, stage}));
    }
    return {};
  }

  BindingPlan finish() && {
    for (auto& [slot, binding] : slots_) {
      plan_.set_count = std::max(plan_.set_count, slot.first + 1);
      plan_.bindings.push_back(std::move(binding));
    }
    return std::move(plan_);
  }

 private:
  Error fail(std::string message) const {
    return make_error(Error::Kind::bad_input, std::string(pass_), std::move(message));
  }

  Result<BindingRole> role_of(const SampledImage& image, const ShaderInterface& iface) const {
    const bool is_cmp = image.name == kShadowCmp;
    if (image.name != kShadowDepth && !is_cmp && image.name != kReceivers) {
      return fail("sampler '" + image.name + "' (" + stage_name(iface) +
                  " stage) is not part of the shader interface; allowed names: " +
                  std::string(kShadowDepth) + ", " + std::string(kShadowCmp) + ", " +
                  std::string(kReceivers));
    }
    if (image.comparison != is_cmp) {
      return fail("sampler '" + image.name + "' must be a " +
                  (is_cmp ? "sampler2DShadow (comparison sampler)" : "sampler2D (no comparison)"));
    }
    if (is_cmp) return BindingRole::map_comparison;
    if (image.name == kReceivers) return BindingRole::receivers;
    // Without a comparison sampler the shader compares itself, on the R32F map (DX9 style).
    return has_comparison_ ? BindingRole::map_depth : BindingRole::map_colour;
  }

  Status add(PlannedBinding binding) {
    if (std::find(available_.begin(), available_.end(), binding.name) == available_.end()) {
      return fail("'" + binding.name + "' has nothing to bind to in the " + std::string(pass_) +
                  ", which binds: " + joined(available_));
    }
    const std::pair slot{binding.set, binding.binding};
    if (auto named = slot_of_.find(binding.name);
        named != slot_of_.end() && named->second != slot) {
      return fail("'" + binding.name + "' is at " + slot_name(slot.first, slot.second) +
                  " in one stage and at " + slot_name(named->second.first, named->second.second) +
                  " in the other");
    }
    slot_of_.emplace(binding.name, slot);
    auto [it, inserted] = slots_.try_emplace(slot, binding);
    if (!inserted && it->second.name != binding.name) {
      return fail("'" + it->second.name + "' and '" + binding.name + "' share " +
                  slot_name(slot.first, slot.second));
    }
    it->second.stages |= binding.stages;
    return {};
  }

  Status merge_members(const UniformBlock& block) {
    plan_.params.size = std::max(plan_.params.size, block.size);
    for (const BlockMember& member : block.members) {
      auto& members = plan_.params.members;
      auto same_name = std::find_if(members.begin(), members.end(),
                                    [&](const BlockMember& m) { return m.name == member.name; });
      if (same_name == members.end()) {
        members.push_back(member);
      } else if (same_name->offset != member.offset || same_name->size != member.size) {
        return fail(std::string(kParamsBlock) + " member '" + member.name +
                    "' has a different offset or size in the two stages");
      }
    }
    return {};
  }

  std::string_view pass_;
  std::span<const std::string_view> available_;
  bool has_comparison_;
  BindingPlan plan_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, PlannedBinding> slots_;
  std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> slot_of_;
};

bool declares_comparison(const ShaderInterface& iface) {
  return std::any_of(iface.sampled_images.begin(), iface.sampled_images.end(),
                     [](const SampledImage& image) { return image.name == kShadowCmp; });
}

}  // namespace

Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass,
                                  std::span<const std::string_view> available) {
  const bool has_comparison =
      declares_comparison(program.vert.iface) || declares_comparison(program.frag.iface);
  Planner planner(pass, available, has_comparison);
  PENUMBRA_TRY(planner.add_stage(program.vert.iface, VK_SHADER_STAGE_VERTEX_BIT));
  PENUMBRA_TRY(planner.add_stage(program.frag.iface, VK_SHADER_STAGE_FRAGMENT_BIT));
  return std::move(planner).finish();
}

}  // namespace penumbra::detail
