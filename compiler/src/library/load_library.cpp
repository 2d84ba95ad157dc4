#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/library.hpp"
#include "penumbra/support/file.hpp"

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

// pass_files[i].bytecode.<stage> (docs/shader-interface.md).
BytecodeFile bytecode_file(const json& j) {
  return BytecodeFile{j.at("path").get<std::string>(), j.at("profile").get<std::string>(),
                      j.at("size").get<std::uint64_t>(), j.value("instruction_slots", 0)};
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

// index.json's shared tables, read once; variants refer to their records by
// position.
struct SharedTables {
  std::vector<PassFiles> pass_files;
  std::vector<PassReflection> reflections;
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
    return index_error(file, path, "reference " + ref.dump() + " is out of range; " + allowed);
  }
  return &table[ref.get<std::size_t>()];
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
          std::string("malformed pass files (docs/shader-interface.md): ") + e.what());
    }
  }
  // Each record's constant textures refer to texture_contents by position (a
  // malformed one is reported at the record that uses it).
  const json& contents_table = j.at("texture_contents");
  const std::vector<json> contents(contents_table.begin(), contents_table.end());
  const json& reflections = j.at("reflections");
  for (std::size_t i = 0; i < reflections.size(); ++i) {
    const std::string at = "/reflections/" + std::to_string(i);
    json record = reflections[i];
    for (const char* stage : {"vert", "frag"}) {
      if (!record.contains(stage) || !record[stage].contains("textures")) continue;
      json& textures = record[stage]["textures"];
      for (std::size_t t = 0; t < textures.size(); ++t) {
        if (!textures[t].is_object() || !textures[t].contains("contents")) continue;
        auto texels = resolve(file, textures[t]["contents"],
                              at + "/" + stage + "/textures/" + std::to_string(t) + "/contents",
                              contents, "texture_contents");
        if (!texels) return texels.error();
        textures[t]["contents"] = **texels;
      }
    }
    try {
      out.reflections.push_back(record.get<PassReflection>());
    } catch (const json::exception& e) {
      return index_error(
          file, at, std::string("malformed reflection (docs/shader-interface.md): ") + e.what());
    }
  }
  const json& disks = j.at("disks");
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const std::string at = "/disks/" + std::to_string(i);
    try {
      out.disks.push_back(disk_from_json(disks[i].at("points"), disks[i]));
    } catch (const json::exception& e) {
      return index_error(file, at, std::string("malformed disk (docs/disks.md): ") + e.what());
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

Result<LibraryVariant> read_variant(const std::filesystem::path& file, const json& j,
                                    const std::string& path, const SharedTables& tables) {
  LibraryVariant out;
  Variant& v = out.variant;
  v.name = j.at("name").get<std::string>();
  auto technique = parse_technique(j.at("technique").get<std::string>());
  if (!technique) {
    return index_error(file, path + "/technique",
                       "unknown technique; allowed: " + allowed_techniques());
  }
  v.technique = *technique;
  const json& keys = j.at("keys");
  for_each_key(v.keys, [&keys](std::string_view name, auto& key) {
    using Value = typename std::decay_t<decltype(key)>::value_type;
    const std::string member(name);
    if (keys.contains(member)) key = keys[member].get<Value>();
  });
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
    for (const json& w : j["blur_weights"]) {
      v.blur_weights.push_back(w.get<float>());
      if (!in_range(v.blur_weights.back(), 0.0f, 1.0f)) {
        return index_error(file,
                           path + "/blur_weights/" + std::to_string(v.blur_weights.size() - 1),
                           "out of range; allowed: a weight from 0 to 1");
      }
    }
  }
  for (const json& t : j.at("targets")) {
    auto target = parse_target(t.get<std::string>());
    if (!target) {
      return index_error(file, path + "/targets", "unknown target; allowed: " + allowed_targets());
    }
    v.targets.push_back(*target);
  }
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
      auto reflection = resolve(file, j.at(pointer), path + at, tables.reflections, "reflections");
      if (!reflection) return reflection.error();
      out.reflection[pass][*target] = **reflection;
    }
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
                      "cannot open the library index (run `penumbra build` first)");
  }
  Library library;
  library.root = root;
  try {
    const json j = json::parse(*text);
    library.generator = j.at("generator").get<std::string>();
    if (j.value("schema", 0) != kIndexSchema) {
      return index_error(file, "/schema",
                         "index schema " + j.value("schema", json()).dump() +
                             " is not supported; allowed value " + std::to_string(kIndexSchema) +
                             " (rebuild the library with this penumbra)");
    }
    const auto tables = read_tables(file, j);
    if (!tables) return tables.error();
    const json& variants = j.at("variants");
    for (std::size_t i = 0; i < variants.size(); ++i) {
      auto v = read_variant(file, variants[i], "/variants/" + std::to_string(i), *tables);
      if (!v) return v.error();
      library.variants.push_back(std::move(*v));
    }
  } catch (const json::exception& e) {
    return make_error(Error::Kind::bad_input, file.string(),
                      std::string("malformed library index: ") + e.what());
  }
  return library;
}

Result<std::vector<std::uint32_t>> read_spirv_file(const std::filesystem::path& path) {
  const Result<std::string> bytes = read_file(path);
  if (!bytes) return make_error(Error::Kind::io, path.string(), "cannot open the SPIR-V file");
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
