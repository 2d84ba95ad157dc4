// screen_blur's blur passes, their composition and the composite.
#include "penumbra/reference/screen_blur.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fixtures.hpp"

namespace penumbra::reference {
namespace {

using testing::binomial5;
using testing::blur_variant;

// A W x H 1-channel image with value(x, y) at each pixel.
template <typename F>
FloatImage image(int width, int height, F value) {
  FloatImage out(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) out.at(x, y) = float(value(x, y));
  }
  return out;
}

// Receivers (u, v, z_r) whose z is z(x, y); u and v are unused by the blur.
template <typename F>
FloatImage receivers_with_z(int width, int height, F z) {
  FloatImage out(width, height, 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) out.at(x, y, 2) = float(z(x, y));
  }
  return out;
}

FloatImage transpose(const FloatImage& in) {
  FloatImage out(in.height, in.width, in.channels);
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) {
      for (int c = 0; c < in.channels; ++c) out.at(y, x, c) = in.at(x, y, c);
    }
  }
  return out;
}

TEST(ScreenBlur, ConstantStaysConstantUpToTheEdges) {
  const FloatImage constant(5, 4, 1, 0.7f);
  const FloatImage flat_z = receivers_with_z(5, 4, [](int, int) { return 10.0; });
  for (const FloatImage* depth : {static_cast<const FloatImage*>(nullptr), &flat_z}) {
    for (const FloatImage& out : {blur_horizontal(constant, binomial5(), depth),
                                  blur_vertical(constant, binomial5(), depth)}) {
      ASSERT_EQ(out.width, 5);
      ASSERT_EQ(out.height, 4);
      ASSERT_EQ(out.channels, 1);
      for (float value : out.data) EXPECT_EQ(value, 0.7f);
    }
  }
}

TEST(ScreenBlur, ImpulseGivesTheWeights) {
  const std::vector<float> w = binomial5();
  const FloatImage row = image(9, 1, [](int x, int) { return x == 4 ? 1.0 : 0.0; });
  const FloatImage h = blur_horizontal(row, w, nullptr);
  const FloatImage v = blur_vertical(transpose(row), w, nullptr);
  for (int x = 0; x < 9; ++x) {
    const float expected = x >= 2 && x <= 6 ? w[std::size_t(x - 2)] : 0.0f;
    EXPECT_EQ(h.at(x, 0), expected) << x;
    EXPECT_EQ(v.at(0, x), expected) << x;
  }
}

TEST(ScreenBlur, ImpulseOfAnAsymmetricKernelIsMirrored) {
  // out(x) = sum_k w_k F(x + k): an impulse at 4 lands tap k at x = 4 - k.
  const std::vector<float> w = {0.5f, 0.25f, 0.25f};
  const FloatImage row = image(9, 1, [](int x, int) { return x == 4 ? 1.0 : 0.0; });
  const FloatImage h = blur_horizontal(row, w, nullptr);
  EXPECT_EQ(h.at(5, 0), 0.5f);
  EXPECT_EQ(h.at(4, 0), 0.25f);
  EXPECT_EQ(h.at(3, 0), 0.25f);
}

TEST(ScreenBlur, StepAtTheEdgeRepeatsTheEdgePixel) {
  // F = 1 only at pixel 0. Taps past the edge read pixel 0, so with weights
  // (1, 4, 6, 4, 1) / 16: out(0) = (1 + 4 + 6) / 16, out(1) = (1 + 4) / 16,
  // out(2) = 1 / 16. Zero padding would give 6/16, 4/16, 1/16.
  const std::vector<float> expected = {11.0f / 16, 5.0f / 16, 1.0f / 16, 0.0f, 0.0f, 0.0f};
  const FloatImage left = image(6, 2, [](int x, int) { return x == 0 ? 1.0 : 0.0; });
  const FloatImage h = blur_horizontal(left, binomial5(), nullptr);
  const FloatImage v = blur_vertical(transpose(left), binomial5(), nullptr);
  // The right edge, mirrored.
  const FloatImage right = image(6, 2, [](int x, int) { return x == 5 ? 1.0 : 0.0; });
  const FloatImage hr = blur_horizontal(right, binomial5(), nullptr);
  for (int x = 0; x < 6; ++x) {
    for (int y = 0; y < 2; ++y) {
      EXPECT_EQ(h.at(x, y), expected[std::size_t(x)]) << x;
      EXPECT_EQ(v.at(y, x), expected[std::size_t(x)]) << x;
      EXPECT_EQ(hr.at(5 - x, y), expected[std::size_t(x)]) << x;
    }
  }
}

// Columns 0-3 at z 10 with factor (0, 1, 0, 1), columns 4-7 at z 20 with
// factor 0, three identical rows.
struct DepthEdge {
  FloatImage factor = image(8, 3, [](int x, int) { return x < 4 ? x % 2 : 0; });
  FloatImage receivers = receivers_with_z(8, 3, [](int x, int) { return x < 4 ? 10.0 : 20.0; });
};

TEST(ScreenBlur, DepthAwareDoesNotBleedAcrossADiscontinuity) {
  const DepthEdge scene;
  const FloatImage aware = blur_horizontal(scene.factor, binomial5(), &scene.receivers);
  const FloatImage plain = blur_horizontal(scene.factor, binomial5(), nullptr);
  for (int y = 0; y < 3; ++y) {
    // Pixel 3 keeps taps 1, 2, 3 (weights 1, 4, 6), renormalized: 7 / 11.
    EXPECT_FLOAT_EQ(aware.at(3, y), 7.0f / 11);
    // The plain blur also reads 4 and 5: (1 + 6) / 16.
    EXPECT_EQ(plain.at(3, y), 7.0f / 16);
    // The far side stays 0 only when depth-aware: the plain blur at 4 reads
    // pixel 3 with weight 4 / 16.
    for (int x = 4; x < 8; ++x) EXPECT_EQ(aware.at(x, y), 0.0f) << x;
    EXPECT_EQ(plain.at(4, y), 4.0f / 16);
  }
}

TEST(ScreenBlur, DepthAwareVerticalPass) {
  const DepthEdge scene;
  const FloatImage factor = transpose(scene.factor);
  const FloatImage receivers = transpose(scene.receivers);
  const FloatImage aware = blur_vertical(factor, binomial5(), &receivers);
  for (int x = 0; x < 3; ++x) {
    EXPECT_FLOAT_EQ(aware.at(x, 3), 7.0f / 11);
    for (int y = 4; y < 8; ++y) EXPECT_EQ(aware.at(x, y), 0.0f);
  }
}

TEST(ScreenBlur, DepthToleranceIsRelativeToTheCentre) {
  // Centre z 10: a neighbour at 10.1 is within 0.02 * 10, one at 10.3 is not.
  const FloatImage factor = image(3, 1, [](int x, int) { return x == 1 ? 1.0 : 0.0; });
  const std::vector<float> w = {0.25f, 0.5f, 0.25f};
  const FloatImage near_z = receivers_with_z(3, 1, [](int x, int) { return x == 1 ? 10.0 : 10.1; });
  EXPECT_EQ(blur_horizontal(factor, w, &near_z).at(1, 0), 0.5f);
  const FloatImage far_z = receivers_with_z(3, 1, [](int x, int) { return x == 1 ? 10.0 : 10.3; });
  EXPECT_EQ(blur_horizontal(factor, w, &far_z).at(1, 0), 1.0f);
  // At z 100 the same 0.3 difference is within tolerance.
  const FloatImage deep = receivers_with_z(3, 1, [](int x, int) { return x == 1 ? 100.0 : 100.3; });
  EXPECT_EQ(blur_horizontal(factor, w, &deep).at(1, 0), 0.5f);
}

TEST(ScreenBlur, DepthToleranceUsesTheCentresMagnitude) {
  // Centre z -10, neighbours -10.1 (kept) and -10.3 (dropped): the limit is
  // 0.02 * |z_centre|, so the centre is kept (a signed limit would drop
  // every tap and divide by 0). Kept: (0.25 * 1 + 0.5 * 0) / 0.75.
  const FloatImage factor = image(3, 1, [](int x, int) { return x == 1 ? 0.0 : 1.0; });
  const FloatImage z = receivers_with_z(3, 1, [](int x, int) {
    return x == 0 ? -10.1 : x == 1 ? -10.0 : -10.3;
  });
  EXPECT_FLOAT_EQ(blur_horizontal(factor, {{0.25f, 0.5f, 0.25f}}, &z).at(1, 0), 1.0f / 3);
}

TEST(ScreenBlur, ChainFollowsTheDepthAwareKey) {
  const DepthEdge scene;
  const FloatImage aware =
      screen_blur(blur_variant(2, binomial5(), true), scene.factor, scene.receivers);
  const FloatImage plain = screen_blur(blur_variant(2, binomial5()), scene.factor, scene.receivers);
  // Rows are identical and each column has one z, so the vertical pass keeps
  // every value.
  for (int y = 0; y < 3; ++y) {
    EXPECT_FLOAT_EQ(aware.at(3, y), 7.0f / 11);
    EXPECT_EQ(aware.at(4, y), 0.0f);
    EXPECT_EQ(plain.at(3, y), 7.0f / 16);
    EXPECT_EQ(plain.at(4, y), 4.0f / 16);
  }
  // Transposed, the horizontal pass keeps every value and the vertical one
  // meets the discontinuity.
  const FloatImage aware_t = screen_blur(blur_variant(2, binomial5(), true),
                                         transpose(scene.factor), transpose(scene.receivers));
  for (int x = 0; x < 3; ++x) {
    EXPECT_FLOAT_EQ(aware_t.at(x, 3), 7.0f / 11);
    EXPECT_EQ(aware_t.at(x, 4), 0.0f);
  }
}

TEST(ScreenBlur, SeparableEqualsTheDirect2dConvolution) {
  // Gaussian taps for R = 3, sigma = 1.5, normalized, as floats.
  std::vector<float> w;
  double total = 0.0;
  for (int k = -3; k <= 3; ++k) total += std::exp(-k * k / (2 * 1.5 * 1.5));
  for (int k = -3; k <= 3; ++k) w.push_back(float(std::exp(-k * k / (2 * 1.5 * 1.5)) / total));
  const FloatImage factor = testing::random_map(12, 10, 0.0f, 1.0f, 7u);
  const FloatImage chain = screen_blur(blur_variant(3, w), factor, FloatImage(12, 10, 3));
  EXPECT_EQ(chain.data, blur_vertical(blur_horizontal(factor, w, nullptr), w, nullptr).data);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 12; ++x) {
      double direct = 0.0;
      for (int b = -3; b <= 3; ++b) {
        for (int a = -3; a <= 3; ++a) {
          direct += double(w[std::size_t(a + 3)]) * w[std::size_t(b + 3)] *
                    factor.at(std::clamp(x + a, 0, 11), std::clamp(y + b, 0, 9));
        }
      }
      // Only the horizontal pass's float storage separates the two.
      EXPECT_NEAR(chain.at(x, y), direct, 1e-6) << x << ", " << y;
    }
  }
}

TEST(ScreenBlur, ReadsChannelZeroOfAMultiChannelFactor) {
  // The GPU factor target is RG32F: (factor, reads).
  FloatImage factor(4, 1, 2);
  for (int x = 0; x < 4; ++x) factor.at(x, 0, 0) = 0.5f, factor.at(x, 0, 1) = 9.0f;
  for (float value : blur_horizontal(factor, binomial5(), nullptr).data) EXPECT_EQ(value, 0.5f);
}

TEST(ScreenBlurComposite, ScalesRgbAndKeepsAlpha) {
  FloatImage colour(2, 1, 4);
  const float rgba[2][4] = {{1.0f, 0.5f, 0.25f, 0.5f}, {0.2f, 0.4f, 0.8f, 1.0f}};
  for (int x = 0; x < 2; ++x) {
    for (int c = 0; c < 4; ++c) colour.at(x, 0, c) = rgba[x][c];
  }
  const FloatImage blurred = image(2, 1, [](int x, int) { return x == 0 ? 0.5 : 0.3; });
  const FloatImage out = composite(colour, blurred);
  ASSERT_EQ(out.channels, 4);
  EXPECT_EQ(out.at(0, 0, 0), 0.5f);
  EXPECT_EQ(out.at(0, 0, 1), 0.25f);
  EXPECT_EQ(out.at(0, 0, 2), 0.125f);
  EXPECT_EQ(out.at(0, 0, 3), 0.5f);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(out.at(1, 0, c), rgba[1][c] * 0.3f);
  EXPECT_EQ(out.at(1, 0, 3), 1.0f);
}

TEST(ScreenBlurComposite, SceneColourIsAnOpaqueCheckerboard) {
  const FloatImage colour = scene_colour(40, 20);
  ASSERT_EQ(colour.channels, 4);
  ASSERT_EQ(colour.width, 40);
  ASSERT_EQ(colour.height, 20);
  const std::vector<float> even = {1.0f, 0.5f, 0.25f, 1.0f};
  const std::vector<float> odd = {0.25f, 0.75f, 1.0f, 1.0f};
  auto pixel = [&](int x, int y) {
    return std::vector<float>{colour.at(x, y, 0), colour.at(x, y, 1), colour.at(x, y, 2),
                              colour.at(x, y, 3)};
  };
  EXPECT_EQ(pixel(0, 0), even);
  EXPECT_EQ(pixel(15, 15), even);
  EXPECT_EQ(pixel(16, 0), odd);
  EXPECT_EQ(pixel(0, 16), odd);
  EXPECT_EQ(pixel(16, 16), even);
  EXPECT_EQ(pixel(39, 19), odd);  // square (2, 1)
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 40; ++x) EXPECT_EQ(colour.at(x, y, 3), 1.0f);
  }
}

}  // namespace
}  // namespace penumbra::reference
