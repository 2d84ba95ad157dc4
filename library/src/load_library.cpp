#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "penumbra/library/disk_json.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/json_number.hpp"
#include "penumbra/model/json_text.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra {
namespace {

using nlohmann::json;

// Whether low <= value <= high; false for NaN. A number too large for a
// double (1e999) reads as infinite, so this refuses it too.
bool in_range(float value, float low, float high) {
  return value >= low && value <= high;
}

Error index_error(const std::filesystem::path& file, const std::string& path,
                  const std::string& message) {
  return make_error(Error::Kind::bad_input, file.string() + ": " + path, message);
}

// "expected a string, got 5", the value quoted shortly.
Error type_error(const std::filesystem::path& file, const std::string& path,
                 std::string_view expected, const json& value) {
  return index_error(file, path,
                     "expected " + std::string(expected) + ", got " + describe_json(value));
}

// `j`'s member `key`, or an error naming the missing key.
Result<const json*> member(const std::filesystem::path& file, const json& j,
                           const std::string& path, const std::string& key) {
  if (!j.is_object()) return type_error(file, path, "an object", j);
  if (!j.contains(key)) return index_error(file, path, "missing key '" + key + "'");
  return &j[key];
}

Result<std::string> string_at(const std::filesystem::path& file, const json& value,
                              const std::string& path) {
  if (!value.is_string()) return type_error(file, path, "a string", value);
  return value.get<std::string>();
}

// A count key: an integer in 1..`max` (docs/manifest.md, "Limits"), as in a
// manifest, so a library edited by hand cannot ask for a 100001-texel kernel.
Result<int> count_at(const std::filesystem::path& file, const json& value, const std::string& path,
                     std::string_view key, int max) {
  if (!value.is_number_integer()) return type_error(file, path, "an integer", value);
  const bool in_range = value.is_number_unsigned()
                            ? value.get<std::uint64_t>() >= 1 &&
                                  value.get<std::uint64_t>() <= static_cast<std::uint64_t>(max)
                            : value.get<std::int64_t>() >= 1 && value.get<std::int64_t>() <= max;
  if (!in_range) {
    return index_error(file, path,
                       std::string(key) + " " + shorten(value.dump()) +
                           " is out of range; allowed 1.." + std::to_string(max));
  }
  return value.get<int>();
}

// The largest value of each count key.
int max_count(std::string_view key) {
  if (key == "max_nodes") return kMaxMaxNodes;
  if (key == "blur_radius") return kMaxBlurRadius;
  if (key == "light_bits") return kAllowedLightBits.back();  // a square count: check_variant()
  return kMaxSamples;                                        // kernel, blocker_samples, pcf_samples
}

// The variant's keys, typed and range-checked like a manifest's.
Status read_keys(const std::filesystem::path& file, const json& keys, const std::string& path,
                 VariantKeys& out) {
  if (!keys.is_object()) return type_error(file, path, "an object", keys);
  Status status;
  for_each_key(out, [&](std::string_view name, auto& key) {
    using Value = typename std::decay_t<decltype(key)>::value_type;
    const std::string member_name(name);
    if (!status || !keys.contains(member_name)) return;
    const json& value = keys[member_name];
    const std::string at = path + "/" + member_name;
    if constexpr (std::is_same_v<Value, int>) {
      Result<int> count = count_at(file, value, at, name, max_count(name));
      if (!count)
        status = count.error();
      else
        key = *count;
    } else if constexpr (std::is_same_v<Value, bool>) {
      if (!value.is_boolean())
        status = type_error(file, at, "true or false", value);
      else
        key = value.get<bool>();
    } else {
      Result<std::string> text = string_at(file, value, at);
      if (!text)
        status = text.error();
      else if (name == "map_encoding" && !parse_map_encoding(*text))
        status = index_error(
            file, at,
            "unknown map_encoding '" + shorten(*text) + "'; allowed " + allowed_map_encodings());
      else
        key = *text;
    }
  });
  return status;
}

// pass_files[i].bytecode.<stage> (docs/shader-interface.md).
BytecodeFile bytecode_file(const json& j) {
  return BytecodeFile{j.at("path").get<std::string>(), j.at("profile").get<std::string>(),
                      number_as<std::uint64_t>(j.at("size")),
                      j.contains("instruction_slots") ? number_as<int>(j["instruction_slots"]) : 0};
}

// A record of pass_files: the two stages' files and their bytecode.
PassFiles pass_files_from_json(const json& j) {
  PassFiles read;
  read.vert = j.at("vert").get<std::string>();
  read.frag = j.at("frag").get<std::string>();
  const json bytecode = j.value("bytecode", json::object());
  if (bytecode.contains("vert")) read.vert_bytecode = bytecode_file(bytecode["vert"]);
  if (bytecode.contains("frag")) read.frag_bytecode = bytecode_file(bytecode["frag"]);
  return read;
}

// A constant texture of a shared reflection record: the variant that refers
// to the record fills it from its own disk.
struct ConstantTexture {
  bool vertex = false;    // in the record's vert stage, else its frag stage
  std::size_t index = 0;  // in that stage's textures
  TextureId id = TextureId::pcf_disk;
};

// A reflection record as index.json shares it: constant textures empty.
struct SharedReflection {
  PassReflection reflection;
  std::vector<ConstantTexture> constants;
};

// index.json's shared tables, read once; variants refer to their records by
// position.
struct SharedTables {
  std::vector<PassFiles> pass_files;
  std::vector<SharedReflection> reflections;
  std::vector<Disk> disks;
};

// The record `ref` (at JSON path `path`) points at in `table` (`/name`).
template <typename Record>
Result<const Record*> resolve(const std::filesystem::path& file, const json& ref,
                              const std::string& path, const std::vector<Record>& table,
                              std::string_view name) {
  if (!ref.is_number_unsigned() || ref.get<std::size_t>() >= table.size()) {
    const std::string allowed = table.empty() ? "/" + std::string(name) + " is empty"
                                              : "allowed 0.." + std::to_string(table.size() - 1) +
                                                    ", positions in /" + std::string(name);
    return index_error(file, path,
                       "reference " + shorten(ref.dump()) + " is out of range; " + allowed);
  }
  return &table[ref.get<std::size_t>()];
}

// Takes each constant texture's `contents` out of reflection record `record`
// (at `at`): {"disk": "pcf"}, the disk of the variant that refers to it.
Status take_constants(const std::filesystem::path& file, const std::string& at, json& record,
                      std::vector<ConstantTexture>& constants) {
  for (const char* stage : {"vert", "frag"}) {
    if (!record.is_object() || !record.contains(stage) || !record[stage].is_object() ||
        !record[stage].contains("textures") || !record[stage]["textures"].is_array()) {
      continue;
    }
    json& textures = record[stage]["textures"];
    for (std::size_t t = 0; t < textures.size(); ++t) {
      if (!textures[t].is_object() || !textures[t].contains("contents")) continue;
      const std::string where = at + "/" + stage + "/textures/" + std::to_string(t);
      const json& contents = textures[t]["contents"];
      const json name = textures[t].value("name", json());
      const TextureDescription* texture =
          name.is_string() ? find_bound_texture(name.get<std::string>()) : nullptr;
      if (!texture || contents_disk(texture->id).empty()) {
        return index_error(file, where + "/name",
                           "contents for " + shorten(name.dump()) +
                               ", which is no constant texture; allowed: pcf_disk, blocker_disk");
      }
      const std::string disk(contents_disk(texture->id));
      if (!contents.is_object() || contents.size() != 1 || contents.value("disk", json()) != disk) {
        return type_error(file, where + "/contents", "{\"disk\": \"" + disk + "\"}", contents);
      }
      constants.push_back({std::strcmp(stage, "vert") == 0, t, texture->id});
      textures[t].erase("contents");
    }
  }
  return {};
}

Result<SharedTables> read_tables(const std::filesystem::path& file, const json& j) {
  SharedTables out;
  const json& pass_files = j.at("pass_files");
  for (std::size_t i = 0; i < pass_files.size(); ++i) {
    try {
      out.pass_files.push_back(pass_files_from_json(pass_files[i]));
    } catch (const json::exception& e) {
      return index_error(
          file, "/pass_files/" + std::to_string(i),
          "malformed pass files (docs/shader-interface.md): " + json_exception_text(e));
    }
  }
  const json& reflections = j.at("reflections");
  for (std::size_t i = 0; i < reflections.size(); ++i) {
    const std::string at = "/reflections/" + std::to_string(i);
    json record = reflections[i];
    SharedReflection shared;
    PENUMBRA_TRY(take_constants(file, at, record, shared.constants));
    try {
      shared.reflection = record.get<PassReflection>();
    } catch (const json::exception& e) {
      return index_error(
          file, at, "malformed reflection (docs/shader-interface.md): " + json_exception_text(e));
    }
    out.reflections.push_back(std::move(shared));
  }
  const json& disks = j.at("disks");
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const std::string at = "/disks/" + std::to_string(i);
    const json& raw_points = disks[i].at("points");
    if (raw_points.is_array() && raw_points.size() > static_cast<std::size_t>(kMaxSamples)) {
      return index_error(file, at + "/points",
                         std::to_string(raw_points.size()) +
                             " points are too many; allowed at most " +
                             std::to_string(kMaxSamples));
    }
    try {
      out.disks.push_back(disk_from_json(raw_points, disks[i]));
    } catch (const json::exception& e) {
      return index_error(file, at, "malformed disk (docs/disks.md): " + json_exception_text(e));
    }
    const std::vector<Point2>& points = out.disks.back().points;
    for (std::size_t p = 0; p < points.size(); ++p) {
      if (!in_range(points[p][0], -1.0f, 1.0f) || !in_range(points[p][1], -1.0f, 1.0f)) {
        return index_error(file, at + "/points/" + std::to_string(p),
                           "out of range; allowed: coordinates from -1 to 1 (a unit disk)");
      }
    }
  }
  return out;
}

// "forms": those the variant was built in, each one its technique has; a
// library older than forms on demand has every form its technique has.
Status read_forms(const std::filesystem::path& file, const json& j, const std::string& path,
                  Variant& v) {
  if (!j.contains("forms")) {
    v.forms = built_forms(v);
    return {};
  }
  const json& forms = j["forms"];
  if (!forms.is_array()) return type_error(file, path + "/forms", "an array", forms);
  v.forms.clear();
  for (std::size_t i = 0; i < forms.size(); ++i) {
    const std::string at = path + "/forms/" + std::to_string(i);
    PENUMBRA_TRY_ASSIGN(const std::string form_name, string_at(file, forms[i], at));
    const std::optional<Form> form = parse_form(form_name);
    if (!form || !has_form(v.technique, *form)) {
      return index_error(file, at,
                         "unknown form '" + shorten(form_name) + "' for technique " +
                             std::string(to_string(v.technique)) +
                             "; allowed: " + to_string(technique_forms(v.technique)));
    }
    v.forms.push_back(*form);
  }
  v.forms = built_forms(v);  // in kAllForms order, each once
  return {};
}

// Shared reflection record `ref` (at `path`) with `variant`'s disks in its
// constant textures.
Result<PassReflection> variant_reflection(const std::filesystem::path& file, const json& ref,
                                          const std::string& path, const SharedTables& tables,
                                          const Variant& variant) {
  PENUMBRA_TRY_ASSIGN(const SharedReflection* shared,
                      resolve(file, ref, path, tables.reflections, "reflections"));
  PassReflection out = shared->reflection;
  for (const ConstantTexture& constant : shared->constants) {
    TextureBinding& texture = (constant.vertex ? out.vert : out.frag).textures[constant.index];
    texture.contents = texture_contents(constant.id, variant);
    if (!texture.contents) {
      return index_error(file, path,
                         "record " + ref.dump() + "'s texture '" + texture.name + "' holds the " +
                             std::string(contents_disk(constant.id)) +
                             " disk, and this variant has none in its /disks");
    }
  }
  return out;
}

Result<LibraryVariant> read_variant(const std::filesystem::path& file, const json& j,
                                    const std::string& path, const SharedTables& tables) {
  LibraryVariant out;
  Variant& v = out.variant;
  PENUMBRA_TRY_ASSIGN(const json* name, member(file, j, path, "name"));
  PENUMBRA_TRY_ASSIGN(v.name, string_at(file, *name, path + "/name"));
  PENUMBRA_TRY_ASSIGN(const json* technique_name, member(file, j, path, "technique"));
  PENUMBRA_TRY_ASSIGN(const std::string technique_text,
                      string_at(file, *technique_name, path + "/technique"));
  auto technique = parse_technique(technique_text);
  if (!technique) {
    return index_error(
        file, path + "/technique",
        "unknown technique '" + shorten(technique_text) + "'; allowed: " + allowed_techniques());
  }
  v.technique = *technique;
  PENUMBRA_TRY_ASSIGN(const json* keys, member(file, j, path, "keys"));
  PENUMBRA_TRY(read_keys(file, *keys, path + "/keys", v.keys));
  for (auto& [role, ref] : j.at("disks").items()) {
    auto disk = resolve(file, ref, path + "/disks/" + role, tables.disks, "disks");
    if (!disk) return disk.error();
    if (role == "blocker") {
      v.blocker_disk = **disk;
    } else if (role == "pcf") {
      v.pcf_disk = **disk;
    } else {
      return index_error(file, path + "/disks/" + role, "unknown disk; allowed: blocker, pcf");
    }
  }
  if (j.contains("blur_weights")) {
    const json& weights = j["blur_weights"];
    const std::size_t most = 2 * static_cast<std::size_t>(kMaxBlurRadius) + 1;
    if (!weights.is_array() || weights.size() > most) {
      return type_error(file, path + "/blur_weights",
                        "an array of at most " + std::to_string(most) + " numbers", weights);
    }
    for (std::size_t i = 0; i < weights.size(); ++i) {
      if (!weights[i].is_number()) {
        return type_error(file, path + "/blur_weights/" + std::to_string(i), "a number",
                          weights[i]);
      }
      // Checked as a double: a weight beyond float's range must not be cast.
      const double weight = weights[i].get<double>();
      if (!(weight >= 0.0 && weight <= 1.0)) {
        return index_error(file, path + "/blur_weights/" + std::to_string(i),
                           "out of range; allowed: a weight from 0 to 1");
      }
      v.blur_weights.push_back(static_cast<float>(weight));
    }
  }
  PENUMBRA_TRY_ASSIGN(const json* targets, member(file, j, path, "targets"));
  if (!targets->is_array()) return type_error(file, path + "/targets", "an array", *targets);
  for (std::size_t i = 0; i < targets->size(); ++i) {
    const std::string at = path + "/targets/" + std::to_string(i);
    PENUMBRA_TRY_ASSIGN(const std::string target_name, string_at(file, (*targets)[i], at));
    auto target = parse_target(target_name);
    if (!target) {
      return index_error(
          file, at, "unknown target '" + shorten(target_name) + "'; allowed: " + allowed_targets());
    }
    // A library written by hand or by an older penumbra: minmax_pcf ships
    // only where it counts exactly.
    const std::string why = inexact_walk(v, *target);
    if (!why.empty()) return index_error(file, at, why + "; rebuild the library");
    v.targets.push_back(*target);
  }
  PENUMBRA_TRY(read_forms(file, j, path, v));
  for (auto& [pass_name, by_target] : j.at("passes").items()) {
    const std::optional<PassKind> parsed = parse_pass(pass_name);
    if (!parsed) {
      std::string known;
      for (PassKind pass : kAllPassKinds) {
        known += (known.empty() ? "" : ", ") + std::string(to_string(pass));
      }
      return index_error(file, path + "/passes/" + pass_name,
                         "unknown pass; this penumbra knows: " + known);
    }
    const PassKind pass = *parsed;
    for (auto& [target_name, files] : by_target.items()) {
      auto target = parse_target(target_name);
      if (!target) continue;
      auto read = resolve(file, files, path + "/passes/" + pass_name + "/" + target_name,
                          tables.pass_files, "pass_files");
      if (!read) return read.error();
      out.passes[pass][*target] = **read;
      const std::string at = "/reflection/" + pass_name + "/" + target_name;
      const json::json_pointer pointer(at);
      if (!j.contains(pointer)) {
        return index_error(file, path + at, "missing; every pass and target in /passes has one");
      }
      PENUMBRA_TRY_ASSIGN(out.reflection[pass][*target],
                          variant_reflection(file, j.at(pointer), path + at, tables, v));
    }
  }
  if (!j.contains("function")) return out;
  const json& function = j["function"];
  if (!function.is_object()) return type_error(file, path + "/function", "an object", function);
  for (auto& [target_name, form] : function.items()) {
    const std::string at = path + "/function/" + target_name;
    const auto target = parse_target(target_name);
    if (!target) {
      return index_error(
          file, at, "unknown target '" + shorten(target_name) + "'; allowed: " + allowed_targets());
    }
    if (!form.is_object()) return type_error(file, at, "an object", form);
    PENUMBRA_TRY_ASSIGN(const json* path_json, member(file, form, at, "file"));
    PENUMBRA_TRY_ASSIGN(const std::string function_file, string_at(file, *path_json, at + "/file"));
    PENUMBRA_TRY_ASSIGN(const json* position, member(file, form, at, "reflection"));
    PENUMBRA_TRY_ASSIGN(PassReflection reflection,
                        variant_reflection(file, *position, at + "/reflection", tables, v));
    out.function[*target] = {function_file, std::move(reflection)};
  }
  return out;
}

}  // namespace

const LibraryVariant* Library::find(std::string_view name) const {
  for (const LibraryVariant& v : variants) {
    if (v.variant.name == name) return &v;
  }
  return nullptr;
}

Result<Library> load_library(const std::filesystem::path& root) {
  const std::filesystem::path file = root / "index.json";
  const Result<std::string> text = read_file(file);
  if (!text) {
    return make_error(Error::Kind::io, file.string(),
                      text.error().message + " (run `penumbra build` first)");
  }
  if (auto nul = text->find('\0'); nul != std::string::npos) {
    return make_error(Error::Kind::bad_input, file.string(),
                      "malformed library index: a NUL byte at offset " + std::to_string(nul) +
                          "; JSON text may not contain NUL bytes");
  }
  return parse_library(*text, root);
}

Result<Library> parse_library(std::string_view text, const std::filesystem::path& root) {
  const std::filesystem::path file = root / "index.json";
  Library library;
  library.root = root;
  try {
    const json j = json::parse(text);
    library.generator = j.at("generator").get<std::string>();
    if (j.value("schema", json()) != kIndexSchema) {
      return index_error(file, "/schema",
                         "index schema " + shorten(j.value("schema", json()).dump()) +
                             " is not supported; allowed value " + std::to_string(kIndexSchema) +
                             " (rebuild the library with this penumbra)");
    }
    const auto tables = read_tables(file, j);
    if (!tables) return tables.error();
    const json& variants = j.at("variants");
    if (variants.size() > static_cast<std::size_t>(kMaxVariants)) {
      return index_error(file, "/variants",
                         std::to_string(variants.size()) +
                             " variants are too many; allowed at most " +
                             std::to_string(kMaxVariants));
    }
    for (std::size_t i = 0; i < variants.size(); ++i) {
      auto v = read_variant(file, variants[i], "/variants/" + std::to_string(i), *tables);
      if (!v) return v.error();
      library.variants.push_back(std::move(*v));
    }
  } catch (const json::exception& e) {
    return make_error(Error::Kind::bad_input, file.string(),
                      "malformed library index: " + json_exception_text(e));
  }
  return library;
}

Result<std::vector<std::uint32_t>> read_spirv_file(const std::filesystem::path& path) {
  const Result<std::string> bytes = read_file(path);
  if (!bytes) {
    return make_error(Error::Kind::io, path.string(),
                      "cannot read the SPIR-V file (" + bytes.error().message + ")");
  }
  const std::string& data = *bytes;
  if (data.size() < 20 || data.size() % 4 != 0) {
    return make_error(Error::Kind::bad_input, path.string(), "not a SPIR-V module (bad size)");
  }
  std::vector<std::uint32_t> words(data.size() / 4);
  std::memcpy(words.data(), data.data(), data.size());
  if (words[0] != 0x07230203u) {
    return make_error(Error::Kind::bad_input, path.string(), "not a SPIR-V module (bad magic)");
  }
  return words;
}

}  // namespace penumbra
