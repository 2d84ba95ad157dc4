// Maps stored in an engine's depth encoding: the encodings themselves, and
// the reference on them against the same depths stored linearly and
// against a float32 emulation of a shader's encoded comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

constexpr MapEncoding kEncodings[] = {MapEncoding::perspective, MapEncoding::perspective_reversed,
                                      MapEncoding::orthographic};

bool marked(const FloatImage& ambiguous, std::size_t k, Ambiguity reason) {
  return (std::uint16_t(ambiguous.data[k]) & std::uint16_t(reason)) != 0;
}

// `linear` (linear z) as a GPU stores it in `encoding`.
FloatImage encoded(const FloatImage& linear, MapEncoding encoding, const DepthRange& range) {
  FloatImage out = linear;
  for (float& d : out.data) d = float(encode_depth(encoding, d, range));
  return out;
}

TEST(MapEncoding, EndsOfTheRangeAndInverse) {
  const DepthRange range{6.0, 32.0};
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::perspective, 6.0, range), 0.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::perspective, 32.0, range), 1.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::perspective_reversed, 6.0, range), 1.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::perspective_reversed, 32.0, range), 0.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::orthographic, 6.0, range), 0.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::orthographic, 32.0, range), 1.0);
  EXPECT_DOUBLE_EQ(encode_depth(MapEncoding::orthographic, 19.0, range), 0.5);
  EXPECT_DOUBLE_EQ(depth_per_unit(MapEncoding::orthographic, 7.0, range), 26.0);
  for (const MapEncoding e : kAllMapEncodings) {
    double last = encode_depth(e, 6.0, range);
    for (double z = 6.5; z <= 32.0; z += 0.5) {
      EXPECT_NEAR(decode_depth(e, encode_depth(e, z, range), range), z, 1e-12 * z) << to_string(e);
      const double d = encode_depth(e, z, range);
      EXPECT_EQ(d > last, depth_increases(e)) << to_string(e) << " at z = " << z;
      last = d;
    }
    EXPECT_EQ(parse_map_encoding(to_string(e)), e);
  }
  EXPECT_FALSE(parse_map_encoding("reversed"));
}

// A receiver at the depth of the texels it reads is a tie; a bias larger
// than tie_margin() settles it.
// Unorm codes read as code / (2^bits - 1), both ends exact; a unorm map's
// tie margin is one step wider, carried into z.
TEST(DepthFormat, CodesReadAsTheirStepAndWidenTheTieMargin) {
  EXPECT_EQ(unorm_depth(DepthFormat::d16_unorm, 0), 0.0f);
  EXPECT_EQ(unorm_depth(DepthFormat::d16_unorm, 65535), 1.0f);
  EXPECT_EQ(unorm_depth(DepthFormat::d24_unorm, 16777215), 1.0f);
  EXPECT_EQ(unorm_depth(DepthFormat::d16_unorm, 32768), float(32768.0 / 65535.0));
  EXPECT_EQ(depth_step(DepthFormat::d32_float), 0.0);
  EXPECT_EQ(depth_step(DepthFormat::d16_unorm), 1.0 / 65535.0);
  for (const DepthFormat format : kAllDepthFormats) {
    EXPECT_EQ(parse_depth_format(to_string(format)), format);
  }
  EXPECT_FALSE(parse_depth_format("d15_unorm"));

  const DepthRange range{6.0, 32.0};
  reference::EncodedDepth d16{MapEncoding::perspective, range, DepthFormat::d16_unorm};
  const reference::EncodedDepth d32{MapEncoding::perspective, range};
  const double z = 16.0;
  EXPECT_NEAR(reference::tie_margin(d16, z) - reference::tie_margin(d32, z),
              depth_per_unit(MapEncoding::perspective, z, range) / 65535.0, 1e-12);
  // One D16 step at z = 16 moves the stored value's decoding by about that much.
  const double d = encode_depth(MapEncoding::perspective, z, range);
  EXPECT_NEAR(decode_depth(MapEncoding::perspective, d + 1.0 / 65535.0, range) - z,
              depth_per_unit(MapEncoding::perspective, z, range) / 65535.0, 1e-6);
}

TEST(EncodedMap, ReceiverAtTheTexelsDepthIsATieUnlessBiased) {
  const DepthRange range{9.5, 32.0};
  FloatImage linear(16, 16, 1);
  for (float& z : linear.data) z = 16.0f;
  FloatImage receivers(8, 8, 3);
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      receivers.at(i, j, 0) = (float(i) + 0.5f) / 8.0f;
      receivers.at(i, j, 1) = (float(j) + 0.5f) / 8.0f;
      receivers.at(i, j, 2) = 16.0f;
    }
  }
  for (const MapEncoding e : kEncodings) {
    const FloatImage stored = encoded(linear, e, range);
    LightParams light;
    auto tied = evaluate_image(testing::hard_variant(), stored, {e, range}, light, receivers);
    ASSERT_TRUE(tied) << tied.error().message;
    for (std::size_t k = 0; k < tied->ambiguous.data.size(); ++k) {
      EXPECT_TRUE(marked(tied->ambiguous, k, Ambiguity::depth_tie)) << to_string(e) << " " << k;
    }
    light.bias = 1e-3;
    auto biased = evaluate_image(testing::hard_variant(), stored, {e, range}, light, receivers);
    ASSERT_TRUE(biased);
    for (std::size_t k = 0; k < biased->ambiguous.data.size(); ++k) {
      EXPECT_EQ(biased->ambiguous.data[k], 0.0f) << to_string(e) << " " << k;
      EXPECT_EQ(biased->visibility.data[k], 1.0f) << to_string(e) << " " << k;
    }
  }
}

// Whether every float32 encoding a shader may compute for the reference
// z_ref compares with the stored value `stored` as `lit` says. The shader
// (shaderlib/common/map_encoding.glsl) computes (z - n) f / (z (f - n)),
// reversed (f - z) n / (z (f - n)), orthographic (z - n) / (f - n); a
// compiler may divide within 2.5 ulp (here 2 either way), or multiply by
// the divisor's reciprocal, or by the quotient of the far factor and the
// divisor.
bool shader_lit_everywhere_as(bool lit, MapEncoding e, const DepthRange& range, double z_ref,
                              float stored) {
  const bool forward = depth_increases(e);
  const bool orthographic = is_orthographic(e);
  const float n = float(range.near_plane), f = float(range.far_plane), z = float(z_ref);
  const float difference = forward ? z - n : f - z;
  const float factor = orthographic ? 1.0f : forward ? f : n;
  const float divisor = orthographic ? f - n : z * (f - n);
  const float quotient = difference * factor / divisor;
  const float ulp = std::nextafter(std::abs(quotient), 2.0f) - std::abs(quotient);
  std::vector<float> candidates = {difference * (factor / divisor),
                                   difference * factor * (1.0f / divisor)};
  for (int ulps = -2; ulps <= 2; ++ulps) candidates.push_back(quotient + float(ulps) * ulp);
  for (const float reference : candidates) {
    const bool shader_lit = forward ? reference <= stored : reference >= stored;
    if (shader_lit != lit) return false;
  }
  return true;
}

// On every built-in scene: every technique that takes an encoding, the
// min-max ones (their mip built from the decoded map) included, matches on
// an encoded map the same depths stored linearly wherever no depth_tie is
// marked, and a float32 emulation of the shader's comparison agrees with
// hard's result at every receiver the reference leaves decided.
TEST(EncodedMap, MatchesTheLinearMapAndTheShadersComparisonOnEveryScene) {
  const std::vector<Point2> disk = {
      {0.25f, 0.25f}, {-0.25f, 0.25f}, {0.25f, -0.25f}, {-0.25f, -0.25f}};
  const Variant variants[] = {
      testing::hard_variant(),
      testing::grid_variant(3),
      testing::pcss_variant({{0.5f, 0.0f}, {-0.5f, 0.0f}, {0.0f, 0.5f}, {0.0f, -0.5f}}, disk),
      testing::minmax_pcf_variant(8),
      testing::backprojection_variant(),
      testing::bitmask_backprojection_variant(64),
      testing::pcss_minmax_variant(disk)};
  for (const Scene& builtin : builtin_scenes()) {
    for (const MapEncoding e : kEncodings) {
      // An orthographic map's scene is lit by a directional light.
      const Scene scene = for_map_encoding(builtin, e);
      const FloatImage depth =
          ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
      const FloatImage recv = receivers(scene, scene.receivers_width, scene.receivers_height);
      const DepthRange range{scene.light.near_plane, 64.0};
      const FloatImage stored = encoded(depth, e, range);
      // The depths as the encoded map holds them, rounded to float: ties
      // aside, the linear reference decides as the encoded one does.
      FloatImage decoded = stored;
      for (float& d : decoded.data) d = float(decode_depth(e, d, range));
      for (const Variant& variant : variants) {
        const std::string where = scene.name + " " + std::string(to_string(e)) + " " + variant.name;
        auto got = evaluate_image(variant, stored, {e, range}, scene.light, recv);
        auto want = evaluate_image(variant, decoded, scene.light, recv);
        ASSERT_TRUE(got && want) << where;
        std::size_t ties = 0;
        for (std::size_t k = 0; k < got->visibility.data.size(); ++k) {
          if (marked(got->ambiguous, k, Ambiguity::depth_tie)) {
            ++ties;
            continue;
          }
          EXPECT_NEAR(got->visibility.data[k], want->visibility.data[k], 1e-5) << where << " " << k;
        }
        EXPECT_LE(double(ties), 0.02 * double(got->visibility.data.size())) << where;
        if (variant.technique != Technique::hard) continue;
        for (int j = 0; j < recv.height; ++j) {
          for (int i = 0; i < recv.width; ++i) {
            const std::size_t k = std::size_t(j) * recv.width + i;
            if (got->ambiguous.data[k] != 0.0f) continue;
            const double u = recv.at(i, j, 0), v = recv.at(i, j, 1);
            const int ti = std::clamp(int(std::floor(u * stored.width)), 0, stored.width - 1);
            const int tj = std::clamp(int(std::floor(v * stored.height)), 0, stored.height - 1);
            const double z_ref = double(recv.at(i, j, 2)) - scene.light.bias;
            EXPECT_TRUE(shader_lit_everywhere_as(got->visibility.data[k] == 1.0f, e, range, z_ref,
                                                 stored.at(ti, tj)))
                << where << " receiver (" << i << ", " << j << ")";
          }
        }
      }
    }
  }
}

// Just outside tie_margin() every emulated shader encoding decides as the
// exact decoding does, across the range, for both encodings.
TEST(EncodedMap, TieMarginCoversTheShadersEncoding) {
  for (const DepthRange range :
       {DepthRange{9.5, 32.0}, DepthRange{6.0, 64.0}, DepthRange{1.0, 1024.0}}) {
    for (const MapEncoding e : kEncodings) {
      for (double z = range.near_plane * 1.01; z < range.far_plane; z *= 1.013) {
        const float stored = float(encode_depth(e, z, range));
        const double texel = decode_depth(e, stored, range);
        const double margin = tie_margin({e, range}, texel);
        for (const double z_ref : {texel - 1.01 * margin, texel + 1.01 * margin}) {
          EXPECT_TRUE(shader_lit_everywhere_as(z_ref <= texel, e, range, z_ref, stored))
              << to_string(e) << " far " << range.far_plane << " z " << z << " z_ref " << z_ref;
        }
      }
    }
  }
}

}  // namespace
}  // namespace penumbra::reference
