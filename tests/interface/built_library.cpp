#include "built_library.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <utility>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::testing {
namespace {

Result<std::vector<Variant>> default_variants() {
  return load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" /
                       "default.json");
}

// A built library that removes its directory when the process ends.
struct TemporaryLibrary {
  Library library;
  ~TemporaryLibrary() {
    std::error_code ignored;
    std::filesystem::remove_all(library.root, ignored);
  }
};

}  // namespace

std::vector<std::string> default_variant_names() {
  std::vector<std::string> names;
  auto variants = default_variants();
  if (!variants) return {"manifest_error"};  // no such variant: the test fails loudly
  for (const Variant& v : *variants) names.push_back(v.name);
  return names;
}

std::string test_name(std::string name) {
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

Result<const Library*> default_library_of(const std::string& name,
                                          std::initializer_list<Target> targets) {
  static std::map<std::pair<std::string, std::vector<Target>>, std::unique_ptr<TemporaryLibrary>>
      built;
  const auto key = std::make_pair(name, std::vector<Target>(targets));
  if (const auto found = built.find(key); found != built.end()) return &found->second->library;
  PENUMBRA_TRY_ASSIGN(std::vector<Variant> variants, default_variants());
  const auto it = std::find_if(variants.begin(), variants.end(),
                               [&](const Variant& v) { return v.name == name; });
  if (it == variants.end()) {
    return make_error(Error::Kind::bad_input, name, "no such variant in permutations/default.json");
  }
  std::erase_if(it->targets, [&](Target target) {
    return std::find(targets.begin(), targets.end(), target) == targets.end();
  });
  const auto out = std::filesystem::path(::testing::TempDir()) /
                   ("penumbra-interface-" + name + "-" + std::to_string(built.size()) + "-" +
                    std::to_string(::getpid()));
  PENUMBRA_TRY(build_library(std::span(&*it, 1), out, BuildOptions{}, ignore_diagnostics()));
  auto library = std::make_unique<TemporaryLibrary>();
  library->library.root = out;  // removed even when it cannot be read back
  PENUMBRA_TRY_ASSIGN(library->library, load_library(out));
  return &built.emplace(key, std::move(library)).first->second->library;
}

Status prove_default_variant(const std::string& name, Prover prover,
                             std::initializer_list<Target> targets) {
  PENUMBRA_TRY_ASSIGN(const Library* library, default_library_of(name, targets));
  const LibraryVariant* variant = library->find(name);
  if (variant == nullptr) {
    return make_error(Error::Kind::internal, name, "the built library lacks the variant");
  }
  std::string failures;
  for (const Target target : targets) {
    int proved = 0;
    for (const auto& [pass, files] : variant->passes) {
      if (!files.contains(target)) continue;
      ++proved;
      if (auto status = prover(*library, *variant, pass, target); !status) {
        failures += "\n" + status.error().to_string();
      }
    }
    if (proved == 0)
      failures += "\n" + name + ": no pass is built for " + std::string(to_string(target));
  }
  if (failures.empty()) return {};
  return make_error(Error::Kind::compile, name, "reflection not proved:" + failures);
}

}  // namespace penumbra::testing
