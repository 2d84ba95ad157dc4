#include "emitted_texts.hpp"

#include <gtest/gtest.h>

#include "build/pass_plan.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::testing {

const std::vector<Variant>& default_variants() {
  static const std::vector<Variant> variants = [] {
    auto loaded = load_variants(PENUMBRA_SOURCE_DIR "/permutations/default.json");
    return loaded ? *loaded : std::vector<Variant>{};
  }();
  return variants;
}

std::vector<std::string> default_variant_names() {
  std::vector<std::string> names;
  for (const Variant& variant : default_variants()) names.push_back(variant.name);
  return names;
}

const Variant* find_default_variant(const std::string& name) {
  for (const Variant& variant : default_variants()) {
    if (variant.name == name) return &variant;
  }
  return nullptr;
}

std::vector<EmittedStage> emitted_stages(const Variant& variant, Target target) {
  std::vector<EmittedStage> out;
  for (PassKind pass : kAllPassKinds) {
    if (!runs_pass(pass, variant)) continue;
    auto compiled = compile_pass(variant, target, pass);
    EXPECT_TRUE(compiled.ok()) << compiled.error().to_string();
    if (!compiled) continue;
    const std::string prefix = variant.name + "/" + std::string(to_string(target)) + "/" +
                               std::string(to_string(pass)) + ".";
    out.push_back({pass, ShaderStage::vertex, prefix + "vert", std::move(compiled->vert)});
    out.push_back({pass, ShaderStage::fragment, prefix + "frag", std::move(compiled->frag)});
  }
  return out;
}

}  // namespace penumbra::testing
