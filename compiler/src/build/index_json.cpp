#include "build/index_json.hpp"

#include <map>
#include <string>
#include <utility>

#include "build/pass_plan.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/library.hpp"
#include "reflect/reflect_target.hpp"

namespace penumbra {
namespace {

// A top-level table of index.json (`pass_files`, `reflections`,
// `texture_contents`, `disks`):
// each distinct record once, in the order variants first use it; variants
// refer to a record by its position. Most records are shared: the depth and
// min-max passes of every variant, the query pass's reflection of variants
// that differ only in baked constants, a disk that variants bake.
class SharedTable {
 public:
  std::size_t add(nlohmann::json record) {
    const auto [at, added] = positions_.try_emplace(record.dump(), records_.size());
    if (added) records_.push_back(std::move(record));
    return at->second;
  }
  nlohmann::json take() { return std::exchange(records_, nlohmann::json::array()); }

 private:
  nlohmann::json records_ = nlohmann::json::array();
  std::map<std::string, std::size_t> positions_;  // a record's text -> its position
};

struct SharedTables {
  SharedTable pass_files;
  SharedTable reflections;
  SharedTable texture_contents;
  SharedTable disks;
};

// A reflection record as index.json stores it: each constant texture's
// `contents` (hlsl_dx9's disks, hundreds of floats) a position in
// `texture_contents`, so that records differing only in their disks stay
// small.
nlohmann::json reflection_record(const PassReflection& reflection, SharedTables& tables) {
  nlohmann::json record = reflection;
  for (const char* stage : {"vert", "frag"}) {
    if (!record[stage].contains("textures")) continue;
    for (nlohmann::json& texture : record[stage]["textures"]) {
      if (!texture.contains("contents")) continue;
      texture["contents"] = tables.texture_contents.add(std::move(texture["contents"]));
    }
  }
  return record;
}

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

nlohmann::json variant_json(const Variant& variant, const std::vector<ShaderJob>& jobs,
                            SharedTables& tables) {
  nlohmann::json out = {{"name", variant.name},
                        {"technique", to_string(variant.technique)},
                        {"keys", variant_keys_json(variant.keys)}};
  nlohmann::json disks = nlohmann::json::object();
  if (variant.blocker_disk) {
    disks["blocker"] = tables.disks.add(disk_to_json(*variant.blocker_disk));
  }
  if (variant.pcf_disk) disks["pcf"] = tables.disks.add(disk_to_json(*variant.pcf_disk));
  out["disks"] = disks;
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
      nlohmann::json files = nlohmann::json::object();
      for (const PassStageSource& source : pass_plan()) {
        if (source.pass != kind) continue;
        const ShaderJob* job = find_job(jobs, variant, target, source);
        if (!job) continue;
        (source.stage == ShaderStage::vertex ? vert : frag) = job;
        const std::string stage(stage_key(source.stage));
        files[stage] = job->output_path;
        if (job->bytecode) {
          nlohmann::json& bytecode = files["bytecode"][stage];
          bytecode = {{"path", job->bytecode->path},
                      {"profile", job->bytecode->profile},
                      {"size", job->bytecode->size}};
          if (job->bytecode->instruction_slots > 0) {
            bytecode["instruction_slots"] = job->bytecode->instruction_slots;
          }
        }
      }
      if (!files.empty()) passes[pass][target_name] = tables.pass_files.add(std::move(files));
      if (vert && frag) {
        reflection[pass][target_name] = tables.reflections.add(
            reflection_record(join_stages(vert->reflection, frag->reflection), tables));
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
  SharedTables tables;
  nlohmann::json list = nlohmann::json::array();
  for (const Variant& variant : variants) list.push_back(variant_json(variant, jobs, tables));
  out["disks"] = tables.disks.take();
  out["pass_files"] = tables.pass_files.take();
  out["reflections"] = tables.reflections.take();
  out["texture_contents"] = tables.texture_contents.take();
  out["variants"] = list;
  return out;
}

std::string index_text(const nlohmann::json& index) {
  std::string out = "{";
  const char* separator = "\n";
  for (const auto& [key, value] : index.items()) {
    out += separator + std::string("  ") + nlohmann::json(key).dump() + ": ";
    separator = ",\n";
    if (!value.is_array() || value.empty()) {
      out += value.dump();
      continue;
    }
    out += "[";
    const char* record_separator = "\n";
    for (const nlohmann::json& record : value) {
      out += record_separator + std::string("    ") + record.dump();
      record_separator = ",\n";
    }
    out += "\n  ]";
  }
  return out + "\n}\n";
}

}  // namespace penumbra
