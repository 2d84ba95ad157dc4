// d3d_viewport: a vertex stage that flips clip y for Direct3D draws, through
// the flipped viewport, what the unflipped stage draws through the plain one.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "test_programs.hpp"

namespace penumbra {
namespace {

constexpr int kSize = 8;
const test::TestLight kLight;

class ViewportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    engine_ = test::make_engine();
    ASSERT_NE(engine_, nullptr);
  }

  // A quad in the top half of the map: rows 1 to 2 of 8, columns 2 to 4.
  FloatImage render(const PassProgram& program) {
    std::vector<std::array<float, 3>> quad;
    test::add_caster_quad(quad, kLight, 0.25f, 0.625f, 0.125f, 0.375f, 12.0f);
    auto map = engine_->render_depth(program, quad, kSize, kSize,
                                     test::make_params(kLight, kSize, kSize, kSize, kSize));
    EXPECT_TRUE(map) << map.error().to_string();
    if (!map) return {};
    auto depth = engine_->read_shadow_map(**map);
    EXPECT_TRUE(depth) << depth.error().to_string();
    return depth ? *depth : FloatImage();
  }

  std::unique_ptr<Engine> engine_;
};

TEST_F(ViewportTest, FlippedStageWithD3dViewportMatchesThePlainOne) {
  const FloatImage plain = render(test::depth_program());
  PassProgram flipped = test::depth_program("depth_flip_y.vert");
  flipped.d3d_viewport = true;
  const FloatImage d3d = render(flipped);
  ASSERT_EQ(plain.data.size(), static_cast<std::size_t>(kSize * kSize));
  EXPECT_EQ(d3d.data, plain.data);
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const bool in_quad = j >= 1 && j <= 2 && i >= 2 && i <= 4;
      EXPECT_EQ(plain.at(i, j) < 1.0f, in_quad) << "texel " << i << ", " << j;
    }
  }
}

TEST_F(ViewportTest, FlippedStageWithoutD3dViewportLandsUpsideDown) {
  const FloatImage plain = render(test::depth_program());
  const FloatImage upside_down = render(test::depth_program("depth_flip_y.vert"));
  ASSERT_EQ(upside_down.data.size(), plain.data.size());
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      EXPECT_EQ(upside_down.at(i, j), plain.at(i, kSize - 1 - j)) << "texel " << i << ", " << j;
    }
  }
}

}  // namespace
}  // namespace penumbra
