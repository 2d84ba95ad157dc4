#include "default_library.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra::testing {

const std::vector<Variant>& default_variants() {
  static const std::vector<Variant> variants = [] {
    auto loaded = load_variants(PENUMBRA_SOURCE_DIR "/permutations/default.json");
    if (!loaded) {
      // Called while tests are being registered, before a test can fail: an
      // empty list would drop the parameterized tests without a word.
      std::fprintf(stderr, "cannot load the default variants: %s\n",
                   loaded.error().to_string().c_str());
      std::abort();
    }
    return std::move(*loaded);
  }();
  return variants;
}

const Variant* find_default_variant(std::string_view name) {
  for (const Variant& variant : default_variants()) {
    if (variant.name == name) return &variant;
  }
  return nullptr;
}

std::vector<std::string> default_variant_names() {
  std::vector<std::string> names;
  for (const Variant& variant : default_variants()) names.push_back(variant.name);
  return names;
}

std::vector<Target> text_targets() {
  std::vector<Target> out;
  for (Target target : kAllTargets) {
    if (traits(target).is_text) out.push_back(target);
  }
  return out;
}

std::vector<Target> hlsl_targets() {
  std::vector<Target> out;
  for (Target target : kAllTargets) {
    if (traits(target).is_hlsl) out.push_back(target);
  }
  return out;
}

std::string test_name(std::string name) {
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

Result<std::unique_ptr<TemporaryLibrary>> TemporaryLibrary::build(
    std::vector<Variant> variants, const std::vector<Target>& targets,
    const BuildOptions& options) {
  if (!targets.empty()) {
    for (Variant& variant : variants) {
      std::erase_if(variant.targets, [&](Target target) {
        return std::find(targets.begin(), targets.end(), target) == targets.end();
      });
    }
  }
  // Unique among test processes (the pid) and within one (the count).
  static std::atomic<int> count = 0;
  std::unique_ptr<TemporaryLibrary> out(new TemporaryLibrary(
      std::filesystem::path(::testing::TempDir()) /
      ("penumbra-library-" + std::to_string(::getpid()) + "-" + std::to_string(count++))));
  // On failure `out` goes, and the directory with it when it was written.
  PENUMBRA_TRY(build_library(variants, out->root_, options, ignore_diagnostics()));
  PENUMBRA_TRY_ASSIGN(out->library_, load_library(out->root_));
  return out;
}

TemporaryLibrary::~TemporaryLibrary() {
  std::error_code ignored;
  std::filesystem::remove_all(root_, ignored);
}

Result<std::unique_ptr<TemporaryLibrary>> build_default_variant(
    std::string_view name, const std::vector<Target>& targets) {
  const Variant* variant = find_default_variant(name);
  if (variant == nullptr) {
    return make_error(Error::Kind::bad_input, std::string(name),
                      "no such variant in permutations/default.json");
  }
  return TemporaryLibrary::build({*variant}, targets);
}

}  // namespace penumbra::testing
