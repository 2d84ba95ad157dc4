// Every default variant's emitted text, for each text target, pass and
// stage, compiles back through its front end to valid Vulkan SPIR-V that
// keeps the interface the runtime binds: resource names, distinct bindings,
// matching varying locations, the position and depth outputs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "default_library.hpp"
#include "emitted_texts.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"
#include "spirv_inspect.hpp"

namespace penumbra::testing {
namespace {

using ::testing::Contains;

struct Expected {
  std::string front_end;
  std::vector<std::string> shims;
};

Expected expected(Target target, MapEncoding encoding, const EmittedStage& emitted) {
  const int model = traits(target).shader_model;
  if (model == 3) {
    // Vertex shaders output POSITION, the depth pass's fragment shader DEPTH
    // (the library's linear map; an engine's hardware depth is the rasterizer's).
    const bool writes_depth = emitted.pass == PassKind::depth && encoding == MapEncoding::linear;
    if (emitted.stage == ShaderStage::fragment && !writes_depth) {
      return {"glslang HLSL (DX9-compatible)", {}};
    }
    return {"glslang HLSL (DX9-compatible)", {"dx9-output-semantics-as-sv"}};
  }
  if (model != 0) return {"glslang HLSL SM" + std::to_string(model), {}};
  switch (target) {
    case Target::glsl330:
      return {"glslang GLSL 330 (Vulkan relaxed rules)", {}};
    case Target::essl300:
      return {"glslang ESSL 310", {"essl300-version-310"}};
    default:
      return {"glslang GLSL 450", {}};
  }
}

bool is_resource(const SpirvVariable& var) {
  return var.storage_class == kStorageUniformConstant || var.storage_class == kStorageUniform;
}

// A stage variable's name without HLSL's "stage_input." / "@entryPointOutput." prefix.
std::string base_name(const std::string& name) {
  return name.substr(name.rfind('.') + 1);
}

// Non-builtin variables of one storage class, by base name → location.
std::map<std::string, std::uint32_t> locations(const std::vector<SpirvVariable>& vars,
                                               std::uint32_t storage_class) {
  std::map<std::string, std::uint32_t> out;
  for (const SpirvVariable& var : vars) {
    if (var.storage_class != storage_class || var.builtin) continue;
    EXPECT_TRUE(var.location.has_value()) << var.name << " has no location";
    out[base_name(var.name)] = var.location.value_or(~0u);
  }
  return out;
}

// Checks one compiled stage; returns its variables for the cross-stage check.
std::vector<SpirvVariable> check_stage(Target target, MapEncoding encoding,
                                       const EmittedStage& emitted, const FrontEndResult& result) {
  EXPECT_EQ(vulkan_validation_errors(result.spirv), "");
  EXPECT_EQ(result.front_end, expected(target, encoding, emitted).front_end);
  EXPECT_EQ(result.shims, expected(target, encoding, emitted).shims);
  // Every target computes at full precision (ESSL: all highp), as the SPIR-V does.
  EXPECT_FALSE(has_relaxed_precision(result.spirv));

  const std::vector<SpirvVariable> vars = spirv_variables(result.spirv);
  std::vector<std::string> names;
  std::map<std::uint32_t, std::string> by_binding;
  for (const SpirvVariable& var : vars) {
    names.push_back(var.name);
    if (!is_resource(var)) continue;
    EXPECT_EQ(var.set, 0u) << var.name;
    EXPECT_TRUE(var.binding.has_value()) << var.name << " has no binding";
    const auto [at, fresh] = by_binding.emplace(var.binding.value_or(~0u), var.name);
    EXPECT_TRUE(fresh) << var.name << " shares binding " << at->first << " with " << at->second;
  }
  // Names as in the target's SPIR-V (the text's source); every query pass
  // reads its receivers.
  if (emitted.pass == PassKind::query && emitted.stage == ShaderStage::fragment) {
    EXPECT_THAT(names, Contains("receivers"));
  }
  for (const SampledImage& image : emitted.compiled.interface.sampled_images) {
    EXPECT_THAT(names, Contains(image.name));
    if (traits(target).dialect == ReflectionDialect::d3d10) {
      EXPECT_THAT(names, Contains("_" + image.name + "_sampler"));
    }
  }

  const std::set<std::uint32_t> builtins = spirv_builtins(result.spirv);
  if (emitted.stage == ShaderStage::vertex) {
    EXPECT_THAT(builtins, Contains(kBuiltInPosition));
  }
  if (emitted.stage == ShaderStage::fragment) {
    const auto outputs = locations(vars, kStorageOutput);
    EXPECT_EQ(outputs.size(), 1u);  // depth_out, minmax, visibility, blurred or colour: target 0
    for (const auto& [name, location] : outputs) EXPECT_EQ(location, 0u) << name;
    // The library's linear map is written by the shader; an engine's
    // hardware depth (a map_encoding) is the rasterizer's.
    if (emitted.pass == PassKind::depth && encoding == MapEncoding::linear) {
      EXPECT_THAT(builtins, Contains(kBuiltInFragDepth));
    }
    if (emitted.pass == PassKind::depth && encoding != MapEncoding::linear) {
      EXPECT_THAT(builtins, ::testing::Not(Contains(kBuiltInFragDepth)));
    }
  }
  return vars;
}

class FrontEndVariant : public ::testing::TestWithParam<std::string> {};

TEST_P(FrontEndVariant, EveryTextTargetCompilesToVulkanSpirvWithItsInterface) {
  const Variant* variant = find_default_variant(GetParam());
  ASSERT_NE(variant, nullptr);
  int compiled = 0;
  for (Target target : text_targets()) {
    // Every text target, but bitmask_backprojection has no hlsl_dx9 form,
    // nor minmax_pcf above K = 8.
    if (!can_emit(*variant, target)) continue;
    ASSERT_THAT(variant->targets, Contains(target));
    std::vector<SpirvVariable> vertex;
    for (const EmittedStage& emitted : emitted_stages(*variant, target)) {
      SCOPED_TRACE(emitted.name);
      auto result = compile_target_text(target, emitted.stage, emitted.compiled.text, emitted.name);
      ASSERT_TRUE(result.ok()) << result.error().to_string();
      const std::vector<SpirvVariable> vars =
          check_stage(target, map_encoding(variant->keys), emitted, *result);
      ++compiled;
      if (emitted.stage == ShaderStage::vertex) {
        vertex = vars;
        continue;
      }
      // Stages are compiled one at a time: each must place the varyings alike.
      EXPECT_EQ(locations(vertex, kStorageOutput), locations(vars, kStorageInput));
    }
  }
  // Every pass the technique lists: depth and query; the two min-max build
  // passes, screen_blur's three or the deferred pass.
  const int passes = static_cast<int>(describe(variant->technique).passes.size());
  const auto targets = std::ranges::count_if(
      text_targets(), [&](Target target) { return can_emit(*variant, target); });
  EXPECT_EQ(compiled, static_cast<int>(targets) * passes * 2);  // targets, passes, stages
}

INSTANTIATE_TEST_SUITE_P(Default, FrontEndVariant, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

TEST(FrontEndVariants, TheDefaultManifestHasVariants) {
  EXPECT_THAT(default_variant_names(), Contains("hard"));
}

}  // namespace
}  // namespace penumbra::testing
