#include <cstring>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/library.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

using nlohmann::json;

Error index_error(const std::filesystem::path& file, const std::string& path,
                  const std::string& message) {
  return make_error(Error::Kind::bad_input, file.string() + ": " + path, message);
}

// passes.<pass>.<target>.bytecode.<stage> (docs/shader-interface.md).
BytecodeFile bytecode_file(const json& j) {
  return BytecodeFile{j.at("path").get<std::string>(), j.at("profile").get<std::string>(),
                      j.at("size").get<std::uint64_t>(), j.value("instruction_slots", 0)};
}

Result<LibraryVariant> read_variant(const std::filesystem::path& file, const json& j,
                                    const std::string& path) {
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
  const json& disks = j.at("disks");
  const json info = j.value("disk_info", json::object());
  if (disks.contains("blocker")) {
    v.blocker_disk = disk_from_json(disks["blocker"], info.value("blocker", json::object()));
  }
  if (disks.contains("pcf")) {
    v.pcf_disk = disk_from_json(disks["pcf"], info.value("pcf", json::object()));
  }
  if (j.contains("blur_weights")) {
    for (const json& w : j["blur_weights"]) v.blur_weights.push_back(w.get<float>());
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
      PassFiles& read = out.passes[pass][*target];
      read.vert = files.at("vert");
      read.frag = files.at("frag");
      const json bytecode = files.value("bytecode", json::object());
      if (bytecode.contains("vert")) read.vert_bytecode = bytecode_file(bytecode["vert"]);
      if (bytecode.contains("frag")) read.frag_bytecode = bytecode_file(bytecode["frag"]);
      const std::string at = "/reflection/" + pass_name + "/" + target_name;
      try {
        out.reflection[pass][*target] = j.at(json::json_pointer(at)).get<PassReflection>();
      } catch (const json::exception& e) {
        return index_error(
            file, path + at,
            std::string("malformed reflection (docs/shader-interface.md): ") + e.what());
      }
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
                         "unsupported index schema; this penumbra reads " +
                             std::to_string(kIndexSchema) + " (rebuild the library)");
    }
    const json& variants = j.at("variants");
    for (std::size_t i = 0; i < variants.size(); ++i) {
      auto v = read_variant(file, variants[i], "/variants/" + std::to_string(i));
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
