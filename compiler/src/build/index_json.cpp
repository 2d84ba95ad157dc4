#include "build/index_json.hpp"

#include "build/pass_plan.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/library.hpp"
#include "reflect/reflect_target.hpp"

namespace penumbra {
namespace {

// The job that produced `source` for `target` (shared or this variant's).
const ShaderJob* find_job(const std::vector<ShaderJob>& jobs, const Variant& variant, Target target,
                          const PassStageSource& source) {
  for (const ShaderJob& job : jobs) {
    const bool owner = source.per_variant ? job.variant == &variant : job.variant == nullptr;
    if (owner && job.target == target && job.pass == source.pass && job.stage == source.stage) {
      return &job;
    }
  }
  return nullptr;
}

nlohmann::json variant_json(const Variant& variant, const std::vector<ShaderJob>& jobs) {
  nlohmann::json out = {{"name", variant.name},
                        {"technique", to_string(variant.technique)},
                        {"keys", variant_keys_json(variant.keys)}};
  nlohmann::json disks = nlohmann::json::object();
  nlohmann::json disk_info = nlohmann::json::object();
  if (variant.blocker_disk) {
    disks["blocker"] = disk_points_json(*variant.blocker_disk);
    disk_info["blocker"] = disk_info_json(*variant.blocker_disk);
  }
  if (variant.pcf_disk) {
    disks["pcf"] = disk_points_json(*variant.pcf_disk);
    disk_info["pcf"] = disk_info_json(*variant.pcf_disk);
  }
  out["disks"] = disks;
  out["disk_info"] = disk_info;
  if (!variant.blur_weights.empty()) {
    // Exact like the disks: each float widens to double, written shortest.
    nlohmann::json weights = nlohmann::json::array();
    for (float w : variant.blur_weights) weights.push_back(static_cast<double>(w));
    out["blur_weights"] = weights;
  }

  nlohmann::json targets = nlohmann::json::array();
  nlohmann::json passes = nlohmann::json::object();
  nlohmann::json reflection = nlohmann::json::object();
  for (Target target : variant.targets) {
    targets.push_back(to_string(target));
    const std::string target_name(to_string(target));
    for (PassKind kind : describe(variant.technique).passes) {
      const std::string pass(to_string(kind));
      const ShaderJob* vert = nullptr;
      const ShaderJob* frag = nullptr;
      for (const PassStageSource& source : pass_plan()) {
        if (source.pass != kind) continue;
        const ShaderJob* job = find_job(jobs, variant, target, source);
        if (!job) continue;
        (source.stage == ShaderStage::vertex ? vert : frag) = job;
        const std::string stage(stage_key(source.stage));
        passes[pass][target_name][stage] = job->output_path;
        if (job->bytecode) {
          nlohmann::json& bytecode = passes[pass][target_name]["bytecode"][stage];
          bytecode = {{"path", job->bytecode->path},
                      {"profile", job->bytecode->profile},
                      {"size", job->bytecode->size}};
          if (job->bytecode->instruction_slots > 0) {
            bytecode["instruction_slots"] = job->bytecode->instruction_slots;
          }
        }
      }
      if (vert && frag) {
        reflection[pass][target_name] = join_stages(vert->reflection, frag->reflection);
      }
    }
  }
  out["targets"] = targets;
  out["passes"] = passes;
  out["reflection"] = reflection;
  return out;
}

}  // namespace

nlohmann::json variant_keys_json(const VariantKeys& keys) {
  nlohmann::json out = nlohmann::json::object();
  for_each_key(keys, [&out](std::string_view name, const auto& key) {
    if (key) out[std::string(name)] = *key;
  });
  return out;
}

nlohmann::json index_json(std::span<const Variant> variants, const std::vector<ShaderJob>& jobs) {
  nlohmann::json out = {{"generator", "penumbra " + std::string(penumbra_version())},
                        {"schema", kIndexSchema},
                        {"defaults",
                         {{"light_world_size", 0.5},
                          {"light_frustum_width", 3.75},
                          {"near_plane", 9.5},
                          {"bias", 0.0},
                          {"filter_radius_texels", 2.0}}}};
  nlohmann::json list = nlohmann::json::array();
  for (const Variant& variant : variants) list.push_back(variant_json(variant, jobs));
  out["variants"] = list;
  return out;
}

}  // namespace penumbra
