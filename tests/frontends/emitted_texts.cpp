#include "emitted_texts.hpp"

#include <gtest/gtest.h>

#include "build/pass_plan.hpp"

namespace penumbra::testing {

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
