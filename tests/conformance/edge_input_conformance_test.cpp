// Every default variant's shaders on the edge inputs of docs/robustness.md
// ("Edge inputs"), run on the Vulkan device as `penumbra eval` runs them,
// against the CPU reference: SPIR-V (hardware comparison sampler) and
// hlsl_dx9 through glslang's HLSL front end (compares in the shader, a
// capped min-max walk).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "default_library.hpp"
#include "edge_inputs.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/eval.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra::testing {
namespace {

// One pixel per query: columns edge_uvs(), rows edge_depths().
FloatImage edge_receivers(const LightParams& light) {
  const auto uvs = edge_uvs();
  const auto depths = edge_depths(light);
  FloatImage receivers(int(uvs.size()), int(depths.size()), 3);
  for (std::size_t j = 0; j < depths.size(); ++j) {
    for (std::size_t i = 0; i < uvs.size(); ++i) {
      receivers.at(int(i), int(j), 0) = float(uvs[i][0]);
      receivers.at(int(i), int(j), 1) = float(uvs[i][1]);
      receivers.at(int(i), int(j), 2) = float(depths[j]);
    }
  }
  return receivers;
}

class EdgeInputsOnDevice : public ::testing::TestWithParam<std::string> {};

TEST_P(EdgeInputsOnDevice, EveryTargetMatchesTheReference) {
  // hlsl_dx9 where the technique has a form for it (docs/targets.md).
  std::vector<Target> targets = {Target::spirv, Target::hlsl_dx9};
  const Variant* wanted = find_default_variant(GetParam());
  ASSERT_NE(wanted, nullptr);
  std::erase_if(targets, [&](Target target) { return !can_emit(*wanted, target); });
  auto built = build_default_variant(GetParam(), targets);
  ASSERT_TRUE(built) << built.error().to_string();
  const LibraryVariant* variant = (*built)->library().find(GetParam());
  ASSERT_NE(variant, nullptr);
  const Technique technique = variant->variant.technique;
  auto engine = Engine::create(EngineOptions{}, ignore_diagnostics());
  ASSERT_TRUE(engine) << engine.error().to_string();
  const double allowed = reference::tolerance(technique, {}) + 1e-5;
  for (const EdgeMap& map : edge_maps()) {
    for (const EdgeLight& light : edge_lights()) {
      EvalInputs inputs;
      inputs.shadow_map = map.depth;
      inputs.receivers = edge_receivers(light.light);
      inputs.light = light.light;
      for (Target target : targets) {
        const std::string label =
            std::string(to_string(target)) + ", map " + map.name + ", light " + light.name;
        auto device = eval_on_device((*built)->library(), *variant, target, inputs, **engine);
        ASSERT_TRUE(device) << label << ": " << device.error().to_string();
        // `penumbra eval --reference`: on the map as the variant's programs
        // read it (a hardware encoding holds no depth outside its planes),
        // screen_blur's factor blurred as the device's result is.
        auto expected = eval_reference(*variant, target, inputs);
        ASSERT_TRUE(expected) << expected.error().to_string();
        const bool blurred = technique == Technique::screen_blur;
        const FloatImage& want = expected->visibility;
        bool any_ambiguous = false;
        for (float a : expected->ambiguous.data) any_ambiguous = any_ambiguous || a != 0.0f;
        for (int j = 0; j < want.height; ++j) {
          for (int i = 0; i < want.width; ++i) {
            const float got = device->visibility.at(i, j);
            const std::string at = label + ", receiver (" +
                                   std::to_string(inputs.receivers.at(i, j, 0)) + ", " +
                                   std::to_string(inputs.receivers.at(i, j, 1)) + ", " +
                                   std::to_string(inputs.receivers.at(i, j, 2)) + ")";
            EXPECT_TRUE(got >= 0.0f && got <= 1.0f) << at << ": " << got;
            const bool skip = blurred ? any_ambiguous : expected->ambiguous.at(i, j) != 0.0f;
            if (skip) continue;
            EXPECT_LE(std::abs(double(got) - want.at(i, j)), allowed)
                << at << ": device " << got << ", reference " << want.at(i, j);
          }
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Default, EdgeInputsOnDevice, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
