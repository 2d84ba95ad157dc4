#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "build/index_json.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/content_hash.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

struct PartVariant {
  const Variant* variant;  // for the order
  std::size_t part;
  std::size_t index;  // in the part's index.json
};

// Every file a resolved variant names: its passes' shaders and bytecode, and
// its function forms.
std::vector<std::string> variant_files(const ResolvedVariant& variant) {
  std::vector<std::string> files;
  for (const auto& [pass, by_target] : variant.at("passes").items()) {
    for (const auto& [target, record] : by_target.items()) {
      for (const char* stage : {"vert", "frag"}) {
        if (record.contains(stage)) files.push_back(record[stage].get<std::string>());
        if (record.contains("bytecode") && record["bytecode"].contains(stage)) {
          files.push_back(record["bytecode"][stage]["path"].get<std::string>());
        }
      }
    }
  }
  if (variant.contains("function")) {
    for (const auto& [target, form] : variant.at("function").items()) {
      files.push_back(form.at("file").get<std::string>());
    }
  }
  return files;
}

// Copies `file` of `part` into `staging` once; the same path from another
// part (a shared pass) must hold the same bytes. `copied`: path -> hash.
Status copy_file_once(const fs::path& part, const std::string& file, const fs::path& staging,
                      std::map<std::string, std::string>& copied) {
  PENUMBRA_TRY_ASSIGN(const std::string bytes, read_file(part / file));
  const std::string hash = content_hash(bytes);
  const auto [at, added] = copied.try_emplace(file, hash);
  if (!added) {
    if (at->second != hash) {
      return make_error(Error::Kind::bad_input, (part / file).string(),
                        "differs from the same file of an earlier part; parts must come from "
                        "one build setup (same penumbra, shaderlib and HLSL compiler)");
    }
    return {};
  }
  std::error_code ec;
  fs::create_directories((staging / file).parent_path(), ec);
  if (ec) return make_error(Error::Kind::io, (staging / file).parent_path().string(), ec.message());
  return write_file_atomic(staging / file, bytes);
}

}  // namespace

Result<BuildSummary> merge_libraries(std::span<const fs::path> parts, const fs::path& out_dir) {
  // Each part is loaded (which checks it) but only its variants and its
  // index.json are kept: the loaded library's records would double what a
  // merge of thousands of variants holds.
  std::string generator;
  std::vector<std::vector<Variant>> variants;
  std::vector<nlohmann::json> indexes;
  for (const fs::path& part : parts) {
    PENUMBRA_TRY_ASSIGN(Library library, load_library(part));
    if (!variants.empty() && library.generator != generator) {
      return make_error(Error::Kind::bad_input, (part / "index.json").string(),
                        "generator '" + library.generator + "' differs from " +
                            (parts.front() / "index.json").string() + "'s '" + generator +
                            "'; merge parts of one build");
    }
    generator = library.generator;
    std::vector<Variant>& own = variants.emplace_back();
    own.reserve(library.variants.size());
    for (LibraryVariant& entry : library.variants) own.push_back(std::move(entry.variant));
    PENUMBRA_TRY_ASSIGN(const std::string text, read_file(part / "index.json"));
    indexes.push_back(nlohmann::json::parse(text));
  }
  std::vector<PartVariant> order;
  std::map<std::string, std::size_t> owner;
  for (std::size_t p = 0; p < variants.size(); ++p) {
    for (std::size_t i = 0; i < variants[p].size(); ++i) {
      const Variant& variant = variants[p][i];
      if (const auto [at, added] = owner.try_emplace(variant.name, p); !added) {
        return make_error(Error::Kind::bad_input, (parts[p] / "index.json").string(),
                          "variant " + variant.name + " is also in " +
                              (parts[at->second] / "index.json").string() +
                              "; parts must hold disjoint variants");
      }
      order.push_back({&variant, p, i});
    }
  }
  std::ranges::sort(order, [](const PartVariant& a, const PartVariant& b) {
    return variant_less(*a.variant, *b.variant);
  });

  PENUMBRA_TRY(check_output_directory(out_dir));
  PENUMBRA_TRY_ASSIGN(StagedDirectory staged, StagedDirectory::create(out_dir));
  IndexWriter index;
  std::map<std::string, std::string> copied;
  BuildSummary summary;
  for (const PartVariant& entry : order) {
    const ResolvedVariant variant = resolve_variant(indexes[entry.part], entry.index);
    for (const std::string& file : variant_files(variant)) {
      PENUMBRA_TRY(copy_file_once(parts[entry.part], file, staged.staging(), copied));
    }
    index.add(variant);
  }
  PENUMBRA_TRY(write_file_atomic(staged.staging() / "index.json", index.finish()));
  PENUMBRA_TRY(staged.commit_if_changed());
  summary.variants = order.size();
  for (const auto& [file, hash] : copied) {
    (file.ends_with(".d3dbc") || file.ends_with(".dxbc") ? summary.bytecode : summary.files)++;
  }
  return summary;
}

}  // namespace penumbra
