#include "binding_plan.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "binding_roles.hpp"

namespace penumbra::detail {
namespace {

std::string slot_name(std::uint32_t set, std::uint32_t binding) {
  return "set " + std::to_string(set) + " binding " + std::to_string(binding);
}

bool overlaps(const BlockMember& a, const BlockMember& b) {
  return a.offset < b.offset + b.size && b.offset < a.offset + a.size;
}

// Accumulates both stages' resources. Resources on one binding share its
// descriptor: the same resource in both stages, a block both stages declare,
// or a separate image and the sampler paired with it (one combined image
// sampler, which Vulkan lets serve both).
class Planner {
 public:
  Planner(std::string_view pass, std::span<const std::string_view> available)
      : pass_(pass), available_(available) {}

  Status add_stage(const ShaderInterface& iface, bool has_comparison, VkShaderStageFlags stage) {
    auto resources = resolve_stage(iface, has_comparison, pass_);
    if (!resources) return resources.error();
    for (const ResolvedResource& resource : *resources) PENUMBRA_TRY(add(resource, stage));
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

  Status add(const ResolvedResource& resource, VkShaderStageFlags stage) {
    if (std::find(available_.begin(), available_.end(), resource.interface_name) ==
        available_.end()) {
      return fail("'" + resource.name + "' has nothing to bind to in the " + std::string(pass_) +
                  ", which binds: " + joined(available_));
    }
    const std::pair slot{resource.set, resource.binding};
    PENUMBRA_TRY(check_one_slot(resource));
    auto [it, inserted] = slots_.try_emplace(
        slot,
        PlannedBinding{
            resource.name, resource.set, resource.binding, resource.role, resource.type, 0, {}});
    PlannedBinding& binding = it->second;
    if (!inserted && binding.role != resource.role) {
      return fail("'" + binding.name + "' and '" + resource.name + "' share " +
                  slot_name(slot.first, slot.second));
    }
    if (binding.type != resource.type) binding.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    binding.stages |= stage;
    if (resource.block) return merge_members(binding.params, *resource.block);
    return {};
  }

  // An image or sampler is one resource in both stages. Blocks are not: each
  // binding gets its own buffer, so each stage's global block may have its own.
  Status check_one_slot(const ResolvedResource& resource) {
    if (resource.block) return {};
    const std::pair slot{resource.set, resource.binding};
    if (auto named = slot_of_.find(resource.name);
        named != slot_of_.end() && named->second != slot) {
      return fail("'" + resource.name + "' is at " + slot_name(slot.first, slot.second) +
                  " in one stage and at " + slot_name(named->second.first, named->second.second) +
                  " in the other");
    }
    slot_of_.emplace(resource.name, slot);
    return {};
  }

  // Members are matched by their ParamBlock key, so two stages may spell one
  // member differently; distinct members must not share bytes of the buffer.
  Status merge_members(ParamsLayout& layout, const UniformBlock& block) const {
    if (layout.block.empty()) layout.block = block.type_name;
    layout.size = std::max(layout.size, block.size);
    for (const BlockMember& member : block.members) {
      const std::string_view key = param_block_key(member.name);
      const auto& members = layout.members;
      const auto same = std::find_if(members.begin(), members.end(), [&](const BlockMember& m) {
        return param_block_key(m.name) == key;
      });
      if (same != members.end()) {
        if (same->offset == member.offset && same->size == member.size) continue;
        return fail(layout.block + " member '" + member.name +
                    "' has a different offset or size in the two stages");
      }
      const auto clash = std::find_if(members.begin(), members.end(),
                                      [&](const BlockMember& m) { return overlaps(m, member); });
      if (clash != members.end()) {
        return fail(layout.block + " members '" + clash->name + "' and '" + member.name +
                    "' overlap at " + slot_name(block.set, block.binding) +
                    ": the stages share that binding's buffer, so their blocks must agree "
                    "(give each stage's block its own binding)");
      }
      layout.members.push_back(member);
    }
    return {};
  }

  std::string_view pass_;
  std::span<const std::string_view> available_;
  BindingPlan plan_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, PlannedBinding> slots_;
  std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> slot_of_;
};

}  // namespace

Result<BindingPlan> plan_bindings(const PassProgram& program, std::string_view pass,
                                  std::span<const std::string_view> available) {
  const bool has_comparison = declares_comparison(program);
  Planner planner(pass, available);
  PENUMBRA_TRY(planner.add_stage(program.vert.iface, has_comparison, VK_SHADER_STAGE_VERTEX_BIT));
  PENUMBRA_TRY(planner.add_stage(program.frag.iface, has_comparison, VK_SHADER_STAGE_FRAGMENT_BIT));
  return std::move(planner).finish();
}

}  // namespace penumbra::detail
