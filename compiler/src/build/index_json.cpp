#include "build/index_json.hpp"

#include <string>
#include <utility>

#include "build/pass_plan.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/library/disk_json.hpp"
#include "penumbra/library/library.hpp"
#include "reflect/reflect_target.hpp"

namespace penumbra {
namespace {

// A top-level table of index.json (`pass_files`, `reflections`, `disks`):
// each distinct record once; variants refer to a record by its position.
// Most records are shared: the depth and min-max passes of every variant, the
// reflection of variants that differ only in baked constants or disks, a disk
// that variants bake.
// Records are kept as text: a parsed record takes several times the memory.
class SharedTable {
 public:
  std::size_t add(const nlohmann::json& record) {
    const auto [at, added] = positions_.try_emplace(record.dump(), records_.size());
    if (added) records_.push_back(&at->first);
    return at->second;
  }
  const std::vector<const std::string*>& records() const { return records_; }

 private:
  std::map<std::string, std::size_t> positions_;  // a record's text -> its position
  std::vector<const std::string*> records_;       // the texts, by position
};

constexpr const char* kStages[] = {"vert", "frag"};

nlohmann::json files_json(const ShaderJob* vert, const ShaderJob* frag) {
  nlohmann::json files = nlohmann::json::object();
  for (const ShaderJob* job : {vert, frag}) {
    if (!job) continue;
    const std::string stage(stage_key(job->stage));
    files[stage] = job->output_path;
    if (!job->bytecode) continue;
    nlohmann::json& bytecode = files["bytecode"][stage];
    bytecode = {{"path", job->bytecode->path},
                {"profile", job->bytecode->profile},
                {"size", job->bytecode->size}};
    if (job->bytecode->instruction_slots > 0) {
      bytecode["instruction_slots"] = job->bytecode->instruction_slots;
    }
  }
  return files;
}

}  // namespace

struct IndexWriter::Tables {
  SharedTable pass_files;
  SharedTable reflections;
  SharedTable disks;
};

nlohmann::json variant_keys_json(const VariantKeys& keys) {
  nlohmann::json out = nlohmann::json::object();
  for_each_key(keys, [&out](std::string_view name, const auto& key) {
    if (key) out[std::string(name)] = *key;
  });
  return out;
}

JobTable::JobTable(const std::vector<ShaderJob>& jobs) {
  for (const ShaderJob& job : jobs) {
    jobs_[{job.variant, job.target, job.pass, job.stage, job.map_encoding, job.form}] = &job;
  }
}

const ShaderJob* JobTable::find(const Variant& variant, Target target, PassKind pass,
                                ShaderStage stage) const {
  for (const PassStageSource& source : pass_plan()) {
    if (source.pass != pass || source.stage != stage) continue;
    const auto found = jobs_.find({source.per_variant ? &variant : nullptr, target, pass, stage,
                                   job_encoding(source, variant), ShaderForm::pass});
    return found == jobs_.end() ? nullptr : found->second;
  }
  return nullptr;
}

const ShaderJob* JobTable::function(const Variant& variant, Target target) const {
  const auto found = jobs_.find({&variant, target, PassKind::query, ShaderStage::fragment,
                                 map_encoding(variant.keys), ShaderForm::function});
  return found == jobs_.end() ? nullptr : found->second;
}

ResolvedVariant resolve_variant(const Variant& variant, const JobTable& jobs) {
  nlohmann::json out = {{"name", variant.name},
                        {"technique", to_string(variant.technique)},
                        {"keys", variant_keys_json(variant.keys)}};
  nlohmann::json disks = nlohmann::json::object();
  if (variant.blocker_disk) disks["blocker"] = disk_to_json(*variant.blocker_disk);
  if (variant.pcf_disk) disks["pcf"] = disk_to_json(*variant.pcf_disk);
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
  nlohmann::json function = nlohmann::json::object();
  for (Target target : variant.targets) {
    const std::string target_name(to_string(target));
    targets.push_back(target_name);
    if (const ShaderJob* job = jobs.function(variant, target)) {
      function[target_name] = {{"file", job->output_path}, {"reflection", job->reflection}};
    }
    for (PassKind kind : describe(variant.technique).passes) {
      const std::string pass(to_string(kind));
      const ShaderJob* vert = jobs.find(variant, target, kind, ShaderStage::vertex);
      const ShaderJob* frag = jobs.find(variant, target, kind, ShaderStage::fragment);
      if (vert || frag) passes[pass][target_name] = files_json(vert, frag);
      if (vert && frag) {
        reflection[pass][target_name] = join_stages(vert->reflection, frag->reflection);
      }
    }
  }
  out["targets"] = targets;
  nlohmann::json forms = nlohmann::json::array();
  for (Form form : built_forms(variant)) forms.push_back(std::string(to_string(form)));
  out["forms"] = forms;
  out["passes"] = passes;
  out["reflection"] = reflection;
  if (!function.empty()) out["function"] = function;
  return out;
}

ResolvedVariant resolve_variant(const nlohmann::json& index, std::size_t i) {
  nlohmann::json out = index.at("variants").at(i);
  for (auto& [role, position] : out["disks"].items()) {
    position = index.at("disks").at(position.get<std::size_t>());
  }
  for (auto& [pass, by_target] : out["passes"].items()) {
    for (auto& [target, position] : by_target.items()) {
      position = index.at("pass_files").at(position.get<std::size_t>());
    }
  }
  const nlohmann::json& reflections = index.at("reflections");
  for (auto& [pass, by_target] : out["reflection"].items()) {
    for (auto& [target, position] : by_target.items()) {
      position = reflections.at(position.get<std::size_t>());
    }
  }
  if (out.contains("function")) {
    for (auto& [target, form] : out["function"].items()) {
      form["reflection"] = reflections.at(form["reflection"].get<std::size_t>());
    }
  }
  return out;
}

IndexWriter::IndexWriter() : tables_(std::make_unique<Tables>()) {}
IndexWriter::~IndexWriter() = default;

void IndexWriter::add(const ResolvedVariant& variant) {
  nlohmann::json out = variant;
  for (auto& [role, disk] : out["disks"].items()) disk = tables_->disks.add(disk);
  // Shared records are numbered in the order of the variant's targets, then
  // of its technique's passes (not the alphabetical order of JSON members).
  std::span<const PassKind> passes;
  if (const auto technique = parse_technique(out["technique"].get<std::string>())) {
    passes = describe(*technique).passes;
  }
  for (const nlohmann::json& target_json : out["targets"]) {
    const std::string target = target_json.get<std::string>();
    for (PassKind kind : passes) {
      const std::string pass(to_string(kind));
      if (out["passes"].contains(pass) && out["passes"][pass].contains(target)) {
        nlohmann::json& files = out["passes"][pass][target];
        files = tables_->pass_files.add(files);
      }
      if (!out["reflection"].contains(pass) || !out["reflection"][pass].contains(target)) continue;
      share_record(out["reflection"][pass][target]);
    }
    if (out.contains("function") && out["function"].contains(target)) {
      share_record(out["function"][target]["reflection"]);
    }
  }
  variants_.push_back(out.dump());
}

void IndexWriter::share_record(nlohmann::json& record) {
  for (const char* stage : kStages) {
    if (!record[stage].contains("textures")) continue;
    for (nlohmann::json& texture : record[stage]["textures"]) {
      if (!texture.contains("contents") || texture["contents"].contains("disk")) continue;
      // The reflect stage gives contents only to the disk textures.
      const TextureDescription* described = find_bound_texture(texture["name"].get<std::string>());
      texture["contents"] = {{"disk", contents_disk(described->id)}};
    }
  }
  record = tables_->reflections.add(record);
}

namespace {

// A top-level array member: one record a line.
void append_array(std::string& out, std::string_view name,
                  const std::vector<const std::string*>& records) {
  out += ",\n  \"" + std::string(name) + "\": ";
  if (records.empty()) {
    out += "[]";
    return;
  }
  out += "[";
  const char* separator = "\n";
  for (const std::string* record : records) {
    out += separator;
    out += "    ";
    out += *record;
    separator = ",\n";
  }
  out += "\n  ]";
}

}  // namespace

std::string IndexWriter::finish() {
  const nlohmann::json defaults = {{"light_world_size", 0.5},
                                   {"light_frustum_width", 3.75},
                                   {"near_plane", 9.5},
                                   {"bias", 0.0},
                                   {"filter_radius_texels", 2.0}};
  // Members in alphabetical order, as nlohmann::json writes an object.
  std::string out = "{\n  \"defaults\": " + defaults.dump();
  append_array(out, "disks", tables_->disks.records());
  out +=
      ",\n  \"generator\": " + nlohmann::json("penumbra " + std::string(penumbra_version())).dump();
  append_array(out, "pass_files", tables_->pass_files.records());
  append_array(out, "reflections", tables_->reflections.records());
  out += ",\n  \"schema\": " + std::to_string(kIndexSchema);
  std::vector<const std::string*> variants;
  for (const std::string& variant : variants_) variants.push_back(&variant);
  append_array(out, "variants", variants);
  return out + "\n}\n";
}

}  // namespace penumbra
