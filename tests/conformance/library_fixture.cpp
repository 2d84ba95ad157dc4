#include "library_fixture.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::testing {
namespace {

Result<std::vector<Variant>> default_variants() {
  return load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" /
                       "default.json");
}

}  // namespace

VariantLibrary::~VariantLibrary() {
  std::error_code ignored;
  std::filesystem::remove_all(library.root, ignored);
}

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

std::unique_ptr<VariantLibrary> build_default_variant(const std::string& name, bool with_engine) {
  auto variants = default_variants();
  if (!variants) {
    ADD_FAILURE() << variants.error().to_string();
    return nullptr;
  }
  auto it = std::find_if(variants->begin(), variants->end(),
                         [&](const Variant& v) { return v.name == name; });
  if (it == variants->end()) {
    ADD_FAILURE() << "no variant " << name << " in permutations/default.json";
    return nullptr;
  }
  const auto out = std::filesystem::path(::testing::TempDir()) /
                   ("penumbra-" + name + "-" + std::to_string(::getpid()));
  auto built = build_library(std::span(&*it, 1), out, BuildOptions{}, ignore_diagnostics());
  if (!built) {
    ADD_FAILURE() << built.error().to_string();
    return nullptr;
  }
  auto result = std::make_unique<VariantLibrary>();
  auto loaded = load_library(out);
  if (!loaded) {
    ADD_FAILURE() << loaded.error().to_string();
    return nullptr;
  }
  result->library = std::move(*loaded);
  if (with_engine) {
    auto engine = Engine::create(EngineOptions{}, ignore_diagnostics());
    if (!engine) {
      ADD_FAILURE() << engine.error().to_string();
      return nullptr;
    }
    result->engine = std::move(*engine);
  }
  return result;
}

}  // namespace penumbra::testing
