// embedded_program(): the passes `penumbra embed` compiled into this test
// (vulkan_embedded, from embedded_manifest.json) as the engine runs them,
// against the same passes loaded from the library's files.
#include "penumbra/vulkan/embedded_program.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "penumbra/library/library.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "test_programs.hpp"
#include "vulkan_embedded/shaders.hpp"

namespace penumbra {
namespace {

const VariantKeys kPcss{.blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"};

const shaders::Program& embedded(Target target, PassKind pass) {
  const shaders::Program* program = vulkan_embedded::find(Technique::pcss, kPcss, target, pass);
  EXPECT_NE(program, nullptr) << to_string(target) << " " << to_string(pass);
  static const shaders::Program none;
  return program != nullptr ? *program : none;
}

TEST(EmbeddedProgramTest, TheProgramLoadExecutableMakesOfTheLibrarysFiles) {
  auto library = load_library(PENUMBRA_VULKAN_EMBEDDED_LIBRARY);
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  ASSERT_EQ(library->variants.size(), 1u);
  for (PassKind pass : {PassKind::depth, PassKind::query}) {
    SCOPED_TRACE(to_string(pass));
    auto program = embedded_program(embedded(Target::spirv, pass));
    ASSERT_TRUE(program.ok()) << program.error().to_string();
    auto loaded = load_executable(*library, library->variants[0], pass, Target::spirv);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    const PassProgram& expected = loaded->program;
    EXPECT_EQ(program->vert.spirv, expected.vert.spirv);
    EXPECT_EQ(program->vert.iface, expected.vert.iface);
    EXPECT_EQ(program->frag.spirv, expected.frag.spirv);
    EXPECT_EQ(program->frag.iface, expected.frag.iface);
    EXPECT_EQ(nlohmann::json(program->reflection), nlohmann::json(expected.reflection));
    EXPECT_EQ(program->target, Target::spirv);
    EXPECT_FALSE(program->d3d_viewport || program->gl_clip_depth || program->d3d_bytecode);
  }
}

TEST(EmbeddedProgramTest, RendersASoftShadow) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  auto depth = embedded_program(embedded(Target::spirv, PassKind::depth));
  ASSERT_TRUE(depth.ok()) << depth.error().to_string();
  auto query = embedded_program(embedded(Target::spirv, PassKind::query));
  ASSERT_TRUE(query.ok()) << query.error().to_string();

  // A caster over the map's middle at z = 12, receivers at z = 16 along
  // v = 0.5 from the map's edge (u = 0) to its centre (under the caster).
  const test::TestLight light;
  std::vector<std::array<float, 3>> triangles;
  test::add_caster_quad(triangles, light, 0.25f, 0.75f, 0.25f, 0.75f, 12.0f);
  std::vector<std::array<float, 3>> points;
  for (int i = 0; i < 64; ++i)
    points.push_back({(static_cast<float>(i) + 0.5f) / 128.0f, 0.5f, 16.0f});
  const FloatImage receivers = test::receivers_row(points);
  const ParamBlock params = test::make_params(light, 256, 256, receivers.width, 1);

  auto map = engine->render_depth(*depth, triangles, 256, 256, params);
  ASSERT_TRUE(map.ok()) << map.error().to_string();
  auto visibility = engine->run_query(*query, **map, receivers, params);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_EQ(visibility->at(0, 0), 1.0f);   // far from the caster: lit
  EXPECT_EQ(visibility->at(63, 0), 0.0f);  // under its middle: the umbra
  int penumbra = 0;
  for (float v : visibility->data) penumbra += v > 0.0f && v < 1.0f;
  EXPECT_GE(penumbra, 3);  // a soft edge, several receivers wide
}

TEST(EmbeddedProgramTest, TextTargetsAndBrokenRecordsAreRefused) {
  auto text = embedded_program(embedded(Target::glsl450, PassKind::query));
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(text.error().where, "pcss_b16_p16_whitepaper16 glsl450 query pass");
  EXPECT_THAT(text.error().message, ::testing::HasSubstr("compile_target_text"));

  shaders::Program broken = embedded(Target::spirv, PassKind::query);
  broken.reflection = R"({"vertex_inputs": 3})";
  auto record = embedded_program(broken);
  ASSERT_FALSE(record.ok());
  EXPECT_EQ(record.error().kind, Error::Kind::bad_input);
  EXPECT_THAT(record.error().message, ::testing::HasSubstr("reflection record cannot be read"));

  broken = embedded(Target::spirv, PassKind::query);
  const std::vector<std::uint32_t> garbage = {1, 2, 3, 4, 5, 6};
  broken.fragment.spirv = garbage;
  auto words = embedded_program(broken);
  ASSERT_FALSE(words.ok());
  EXPECT_EQ(words.error().kind, Error::Kind::compile);
  EXPECT_EQ(words.error().where, "pcss_b16_p16_whitepaper16 spirv query pass (fragment stage)");
}

}  // namespace
}  // namespace penumbra
