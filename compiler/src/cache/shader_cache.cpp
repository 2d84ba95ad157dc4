#include "cache/shader_cache.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "penumbra/compiler/build.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/content_hash.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

// Bumped whenever an entry's layout or meaning changes.
constexpr std::string_view kEntryFormat = "penumbra shader cache 1";

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::note:
      return "note";
    case Severity::warning:
      return "warning";
    case Severity::error:
      return "error";
  }
  return "note";
}

Severity parse_severity(const std::string& name) {
  if (name == "warning") return Severity::warning;
  if (name == "error") return Severity::error;
  return Severity::note;
}

// An entry: one line of JSON (sizes, reflection, bytecode record, warnings),
// then the output file's bytes, then the bytecode file's.
struct Entry {
  nlohmann::json meta;
  std::string output;
  std::string bytecode;
};

std::optional<Entry> parse_entry(const std::string& bytes) {
  const std::size_t header_end = bytes.find('\n');
  if (header_end == std::string::npos || bytes.compare(0, header_end, kEntryFormat) != 0) {
    return std::nullopt;
  }
  const std::size_t meta_end = bytes.find('\n', header_end + 1);
  if (meta_end == std::string::npos) return std::nullopt;
  Entry entry;
  entry.meta =
      nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(header_end) + 1,
                            bytes.begin() + static_cast<std::ptrdiff_t>(meta_end), nullptr, false);
  if (entry.meta.is_discarded()) return std::nullopt;
  const std::size_t output_size = entry.meta.value("output_size", std::size_t{0});
  const std::size_t bytecode_size = entry.meta.value("bytecode_size", std::size_t{0});
  if (bytes.size() != meta_end + 1 + output_size + bytecode_size) return std::nullopt;
  entry.output = bytes.substr(meta_end + 1, output_size);
  entry.bytecode = bytes.substr(meta_end + 1 + output_size);
  return entry;
}

bool write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(file.flush());
}

}  // namespace

ShaderCache::ShaderCache(std::filesystem::path dir, std::string toolchain)
    : dir_(std::move(dir)), toolchain_(std::move(toolchain)) {}

std::string ShaderCache::key(const ShaderJob& job) const {
  ContentHash hash;
  hash.add(kEntryFormat).add(toolchain_);
  hash.add(to_string(job.target)).add(to_string(job.pass)).add(to_string(job.stage));
  hash.add(job.source_path).add(job.output_path).add(job.banner());
  hash.add(job.variant ? variant_identity(*job.variant) : std::string());
  hash.add(job.preprocessed);
  return hash.hex();
}

std::filesystem::path ShaderCache::entry_path(const std::string& key) const {
  // Two-digit fan-out keeps directories small at hundreds of thousands of entries.
  return dir_ / "shaders-v1" / key.substr(0, 2) / key;
}

bool ShaderCache::restore(const std::string& key, ShaderJob& job,
                          const std::filesystem::path& root) const {
  const Result<std::string> bytes = read_file(entry_path(key));
  if (!bytes) return false;
  std::optional<Entry> entry = parse_entry(*bytes);
  if (!entry) return false;
  try {
    PassReflection reflection = entry->meta.at("reflection").get<PassReflection>();
    std::optional<BytecodeFile> bytecode;
    if (const auto found = entry->meta.find("bytecode"); found != entry->meta.end()) {
      bytecode = BytecodeFile{found->at("path").get<std::string>(),
                              found->at("profile").get<std::string>(), entry->bytecode.size(),
                              found->at("instruction_slots").get<int>()};
    }
    std::vector<Diagnostic> diagnostics;
    for (const nlohmann::json& d : entry->meta.at("diagnostics")) {
      diagnostics.push_back({parse_severity(d.at("severity").get<std::string>()),
                             d.at("where").get<std::string>(), d.at("message").get<std::string>()});
    }
    if (!write_bytes(root / job.output_path, entry->output)) return false;
    if (bytecode && !write_bytes(root / bytecode->path, entry->bytecode)) return false;
    job.reflection = std::move(reflection);
    job.bytecode = std::move(bytecode);
    job.diagnostics = std::move(diagnostics);
  } catch (const nlohmann::json::exception&) {
    return false;  // damaged: compile afresh, and the store overwrites it
  }
  return true;
}

void ShaderCache::store(const std::string& key, const ShaderJob& job,
                        const std::filesystem::path& root) const {
  const Result<std::string> output = read_file(root / job.output_path);
  if (!output) return;
  std::string bytecode;
  nlohmann::json meta = {{"reflection", job.reflection}, {"output_size", output->size()}};
  if (job.bytecode) {
    const Result<std::string> file = read_file(root / job.bytecode->path);
    if (!file) return;
    bytecode = *file;
    meta["bytecode"] = {{"path", job.bytecode->path},
                        {"profile", job.bytecode->profile},
                        {"instruction_slots", job.bytecode->instruction_slots}};
    meta["bytecode_size"] = bytecode.size();
  }
  nlohmann::json diagnostics = nlohmann::json::array();
  for (const Diagnostic& d : job.diagnostics) {
    diagnostics.push_back(
        {{"severity", severity_name(d.severity)}, {"where", d.where}, {"message", d.message}});
  }
  meta["diagnostics"] = diagnostics;
  const std::filesystem::path path = entry_path(key);
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return;
  (void)write_file_atomic(
      path, std::string(kEntryFormat) + "\n" + meta.dump() + "\n" + *output + bytecode);
}

}  // namespace penumbra
