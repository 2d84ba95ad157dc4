// Reflection of the SPIR-V glslang makes from the text targets' shapes:
// flattened block members, global blocks, separate images and samplers, and
// the JSON round trip of every record.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "text_programs.hpp"

namespace penumbra {
namespace {

std::vector<std::string> member_names(const UniformBlock& block) {
  std::vector<std::string> names;
  for (const BlockMember& member : block.members) {
    names.push_back(member.name + "@" + std::to_string(member.offset) + ":" +
                    std::to_string(member.size));
  }
  return names;
}

TEST(ReflectionTest, Glsl330StructInTheGlobalBlockIsFlattened) {
  const ShaderInterface iface = test::reflected_stage("gl330_compare.frag").iface;
  ASSERT_EQ(iface.uniform_blocks.size(), 1u);
  EXPECT_EQ(iface.uniform_blocks[0].type_name, "gl_DefaultUniformBlock");
  EXPECT_EQ(iface.uniform_blocks[0].size, 64u);
  EXPECT_EQ(member_names(iface.uniform_blocks[0]),
            (std::vector<std::string>{"params.shadow_map_size@0:16", "params.light@16:16",
                                      "params.sampling@32:16", "params.screen_size@48:16"}));
  EXPECT_EQ(iface.sampled_images, (std::vector<SampledImage>{{"shadow_depth", 0, 1, false},
                                                             {"shadow_cmp", 0, 2, true},
                                                             {"receivers", 0, 3, false}}));
}

TEST(ReflectionTest, Dx9GlobalsIncludeTheHalfPixelConstant) {
  const ShaderInterface iface = test::reflected_stage("d3d9_depth.vert").iface;
  ASSERT_EQ(iface.uniform_blocks.size(), 1u);
  EXPECT_EQ(iface.uniform_blocks[0].type_name, "$Global");
  EXPECT_EQ(member_names(iface.uniform_blocks[0]),
            (std::vector<std::string>{"params_shadow_map_size@0:16", "params_light@16:16",
                                      "params_sampling@32:16", "params_screen_size@48:16",
                                      "gl_HalfPixel@64:16"}));
  EXPECT_NE(std::find(iface.builtin_outputs.begin(), iface.builtin_outputs.end(), "Position"),
            iface.builtin_outputs.end());
}

TEST(ReflectionTest, Dx10SeparateImagesAndSamplersPairByName) {
  const ShaderInterface iface = test::reflected_stage("d3d10_compare_ssb.frag").iface;
  ASSERT_EQ(iface.uniform_blocks.size(), 1u);
  EXPECT_EQ(iface.uniform_blocks[0].type_name, "ShadowParams");
  EXPECT_EQ(iface.uniform_blocks[0].members[1].name, "params_light");
  EXPECT_TRUE(iface.sampled_images.empty());
  EXPECT_EQ(iface.separate_images, (std::vector<SeparateImage>{{"shadow_depth", 0, 1, false},
                                                               {"shadow_cmp", 0, 2, true},
                                                               {"receivers", 0, 3, false}}));
  EXPECT_EQ(iface.separate_samplers,
            (std::vector<SeparateSampler>{{"_shadow_depth_sampler", 0, 9, "shadow_depth", false},
                                          {"_shadow_cmp_sampler", 0, 10, "shadow_cmp", true},
                                          {"_receivers_sampler", 0, 11, "receivers", false}}));
}

TEST(ReflectionTest, FragmentDepthIsABuiltinOutputOnlyAsSvDepth) {
  const ShaderInterface depth = test::reflected_stage("d3d9_depth.frag").iface;
  EXPECT_EQ(depth.builtin_outputs, std::vector<std::string>{"FragDepth"});
  const ShaderInterface dx9_semantic = test::reflected_stage("d3d9_depth_depth.frag").iface;
  EXPECT_TRUE(dx9_semantic.builtin_outputs.empty());
  ASSERT_EQ(dx9_semantic.outputs.size(), 2u);
  EXPECT_EQ(dx9_semantic.outputs[1].location, 1u);
}

TEST(ReflectionTest, JsonRoundTripsEveryShape) {
  for (const std::string name : {"gl330_compare.frag", "d3d9_depth.vert", "d3d10_compare.frag",
                                 "d3d10_compare_ssb.frag", "depth.frag"}) {
    const ShaderInterface iface = test::reflected_stage(name).iface;
    const nlohmann::json json = iface;
    EXPECT_EQ(json.get<ShaderInterface>(), iface) << name << ": " << json.dump();
  }
}

TEST(ReflectionTest, JsonWithoutTheNewerFieldsReadsThemAsEmpty) {
  nlohmann::json json = test::reflected_stage("d3d10_compare.frag").iface;
  for (const char* key : {"separate_images", "separate_samplers", "builtin_outputs"}) {
    json.erase(key);
  }
  const auto iface = json.get<ShaderInterface>();
  EXPECT_TRUE(iface.separate_images.empty());
  EXPECT_TRUE(iface.separate_samplers.empty());
  EXPECT_EQ(iface.uniform_blocks.size(), 1u);
}

TEST(ReflectionTest, SamplersPairWithImagesBySpirvCrossHlslNaming) {
  EXPECT_EQ(paired_image_name("_shadow_cmp_sampler"), "shadow_cmp");
  EXPECT_EQ(paired_image_name("_receivers_sampler"), "receivers");
  EXPECT_EQ(paired_image_name("__sampler"), "");
  EXPECT_EQ(paired_image_name("_sampler"), "");
  EXPECT_EQ(paired_image_name("shadow_cmp_sampler"), "");
  EXPECT_EQ(paired_image_name("_shadow_cmp_samplers"), "");
  EXPECT_EQ(paired_image_name("point_clamp"), "");
}

}  // namespace
}  // namespace penumbra
