// Every emitted file of every default variant is accepted by the reference
// front ends: spirv-val for .spv, glslangValidator for GLSL and HLSL (DX9
// in its DX9-compatible mode).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "default_library.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra::testing {
namespace {

struct ToolRun {
  int status = 0;
  std::string output;
};

ToolRun run_tool(const std::string& command) {
  const std::string log =
      ::testing::TempDir() + "penumbra-tool-" + std::to_string(::getpid()) + ".log";
  const int status = std::system((command + " > '" + log + "' 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {status, text.str()};
}

std::string acceptance_command(Target target, ShaderStage stage, const std::string& file) {
  const std::string quoted = "'" + file + "'";
  const std::string st = stage == ShaderStage::vertex ? "vert" : "frag";
  const TargetTraits t = traits(target);
  if (!t.is_text) return std::string(SPIRV_VAL_EXECUTABLE) + " --target-env vulkan1.0 " + quoted;
  if (!t.is_hlsl) return std::string(GLSLANG_VALIDATOR_EXECUTABLE) + " -S " + st + " " + quoted;
  return std::string(GLSLANG_VALIDATOR_EXECUTABLE) + " -V -D -e main -S " + st +
         (t.shader_model == 3 ? " --hlsl-dx9-compatible" : "") + " -o /dev/null " + quoted;
}

class TextAcceptance : public ::testing::TestWithParam<std::string> {};

TEST_P(TextAcceptance, EveryTargetFileIsAccepted) {
  auto built = build_default_variant(GetParam());
  ASSERT_TRUE(built) << built.error().to_string();
  const Library& library = (*built)->library();
  const LibraryVariant* variant = library.find(GetParam());
  ASSERT_NE(variant, nullptr);
  int checked = 0;
  for (const auto& [pass, by_target] : variant->passes) {
    for (const auto& [target, files] : by_target) {
      for (ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
        const std::string& rel = stage == ShaderStage::vertex ? files.vert : files.frag;
        const std::string path = (library.root / rel).string();
        const ToolRun run = run_tool(acceptance_command(target, stage, path));
        EXPECT_EQ(run.status, 0) << rel << " rejected:\n" << run.output;
        ++checked;
      }
    }
  }
  // Every pass the technique lists (depth and query; the two min-max build
  // passes where it reads the mip, screen_blur's blur_h, blur_v and
  // composite, or the deferred pass); two stages, every target.
  const int passes = static_cast<int>(describe(variant->variant.technique).passes.size());
  EXPECT_EQ(checked, passes * 2 * static_cast<int>(variant->variant.targets.size()));
}

INSTANTIATE_TEST_SUITE_P(Default, TextAcceptance, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
