// essl300's reflection proved by Chromium's WebGL 2 (headless, ANGLE on
// SwiftShader): the default library (permutations/default.json) is built
// once, every essl300 program runs through one browser run, and each
// variant's test compares every pass's reflection with what WebGL reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>

#include "default_library.hpp"
#include "webgl_check.hpp"
#include "webgl_page.hpp"

namespace penumbra::testing {
namespace {

// The library and the browser's result, shared by every test (built on
// first use; the library is removed at exit); or why there are none.
struct Shared {
  std::unique_ptr<TemporaryLibrary> built;
  nlohmann::json browser;
  std::string error;

  const Library& library() const { return built->library(); }
};

Status build_and_run(Shared& out) {
  BuildOptions options;
  options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  PENUMBRA_TRY_ASSIGN(out.built, TemporaryLibrary::build(default_variants(), {}, options));
  PENUMBRA_TRY_ASSIGN(out.browser, run_webgl(out.library()));
  if (out.browser.contains("error") || !out.browser.value("webgl2", false)) {
    return make_error(Error::Kind::device, "chromium", "no WebGL 2: " + out.browser.dump());
  }
  std::cout << "WebGL 2: " << out.browser.value("renderer", "") << ", "
            << out.browser.value("version", "") << "\n";
  return {};
}

const Shared& shared() {
  static Shared* const instance = [] {
    static Shared built;
    if (auto status = build_and_run(built); !status) built.error = status.error().to_string();
    return &built;
  }();
  return *instance;
}

// The program of `files` in the browser's result, or null.
const nlohmann::json* find_program(const nlohmann::json& browser, const PassFiles& files) {
  for (const auto& program : browser.at("programs")) {
    if (program.value("vert", "") == files.vert && program.value("frag", "") == files.frag) {
      return &program;
    }
  }
  return nullptr;
}

// Every difference of every essl300 pass of `variant`, one line each.
std::string differences(const LibraryVariant& variant, const nlohmann::json& browser) {
  std::string out;
  for (const auto& [pass, targets] : variant.passes) {
    const auto files = targets.find(Target::essl300);
    if (files == targets.end()) continue;
    const std::string where =
        variant.variant.name + ", " + std::string(to_string(pass)) + " pass, essl300: ";
    const auto reflection = variant.reflection.find(pass);
    if (reflection == variant.reflection.end() || !reflection->second.contains(Target::essl300)) {
      out += where + "no reflection\n";
      continue;
    }
    const nlohmann::json* program = find_program(browser, files->second);
    if (program == nullptr) {
      out += where + "not run by the browser\n";
      continue;
    }
    for (const std::string& line :
         check_pass(reflection->second.at(Target::essl300), *program, browser)) {
      out += where + line + "\n";
    }
  }
  return out;
}

class WebglProof : public ::testing::TestWithParam<std::string> {};

TEST_P(WebglProof, ReflectionMatchesWebgl2) {
  ASSERT_TRUE(shared().error.empty()) << shared().error;
  const LibraryVariant* variant = shared().library().find(GetParam());
  ASSERT_NE(variant, nullptr) << GetParam() << " is not in the built library";
  ASSERT_TRUE(variant->passes.begin() != variant->passes.end()) << GetParam() << " has no passes";
  EXPECT_EQ(differences(*variant, shared().browser), "");
}

// The checker fails: one variant's query pass with a block member renamed
// as glsl330 names it, a comparison texture read as a plain one, a binding
// ES 3.00 cannot have, its vertex input and its extension dropped.
TEST(WebglCheck, CorruptedReflectionIsReported) {
  ASSERT_TRUE(shared().error.empty()) << shared().error;
  const LibraryVariant* found = shared().library().find("pcss_b16_p16_whitepaper16");
  ASSERT_NE(found, nullptr);
  LibraryVariant variant = *found;
  PassReflection& query = variant.reflection.at(PassKind::query).at(Target::essl300);
  ASSERT_FALSE(query.frag.blocks.empty());
  ConstantBinding& light = query.frag.blocks[0].members.at(1);
  ASSERT_EQ(light.name, "ShadowParams.light");
  light.name = "params.light";
  auto cmp = std::find_if(query.frag.textures.begin(), query.frag.textures.end(),
                          [](const TextureBinding& t) { return t.name == "shadow_cmp"; });
  ASSERT_NE(cmp, query.frag.textures.end());
  cmp->type = "sampler2D";
  query.frag.textures.front().binding = 0;
  query.vertex_inputs.clear();
  query.extensions.clear();

  const std::string found_lines = differences(variant, shared().browser);
  for (const std::string expected :
       {"query pass, essl300: block ShadowParams member params.light: in the reflection",
        "block ShadowParams member ShadowParams.light: in WebGL (vec4 at 16), not in the "
        "reflection",
        "getUniformIndices(\"params.light\") finds nothing",
        "texture shadow_cmp: reflection says sampler2D, comparison, WebGL sampler2DShadow, "
        "comparison",
        "binding: in the reflection (present), not in WebGL",
        "input position: in WebGL (location 0, vec2), not in the reflection",
        "EXT_color_buffer_float is needed to render the pass's targets, unlisted"}) {
    EXPECT_NE(found_lines.find(expected), std::string::npos)
        << "expected \"" << expected << "\" in:\n"
        << found_lines;
  }
  EXPECT_EQ(differences(*found, shared().browser), "");
}

INSTANTIATE_TEST_SUITE_P(DefaultLibrary, WebglProof, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
