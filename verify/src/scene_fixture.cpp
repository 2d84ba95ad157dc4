#include "scene_fixture.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "scene_truths.hpp"

namespace penumbra {
namespace {

// A texel's centre lies clear of every occluder edge when the rays through
// points kClearance texels from it, along both axes, meet the surface the
// centre's ray meets: every rasterizer then covers it as the ray cast does,
// whatever its pixel-centre rule, once the geometry is placed by it (D3D9's
// half pixel). A map one row off fails on every edge it crosses. Rasterizers
// place edges to 1/2^subTexelPrecisionBits, at least 1/16 texel (Vulkan,
// D3D10+), so 1/8 leaves room.
constexpr double kClearance = 1.0 / 8.0;

bool same_surface(float a, float b) {
  return std::abs(double(a) - b) <= 1e-3 * std::abs(double(a));
}

}  // namespace

DepthTruth depth_truth(const reference::Scene& scene, int width, int height) {
  DepthTruth truth;
  truth.surface = reference::ray_cast_depth(scene, width, height, scene.far_z);
  std::vector<FloatImage> near;
  for (const std::array<double, 2> within :
       {std::array{kClearance, 0.0}, std::array{-kClearance, 0.0}, std::array{0.0, kClearance},
        std::array{0.0, -kClearance}}) {
    near.push_back(reference::ray_cast_depth(scene, width, height, scene.far_z, within));
  }
  truth.clear.resize(truth.surface.data.size());
  for (std::size_t k = 0; k < truth.clear.size(); ++k) {
    truth.clear[k] = std::all_of(near.begin(), near.end(), [&](const FloatImage& n) {
      return same_surface(truth.surface.data[k], n.data[k]);
    });
  }
  return truth;
}

DepthCheck check_depth(const reference::Scene& scene, Target target, const FloatImage& gpu,
                       const std::string& backend,
                       const std::optional<reference::EncodedDepth>& quantized) {
  return check_depth(depth_truth(scene, gpu.width, gpu.height), scene, target, gpu, backend,
                     quantized);
}

DepthCheck check_depth(const DepthTruth& truth, const reference::Scene& scene, Target target,
                       const FloatImage& gpu, const std::string& backend,
                       const std::optional<reference::EncodedDepth>& quantized) {
  if (truth.surface.width != gpu.width || truth.surface.height != gpu.height) {
    return check_depth(scene, target, gpu, backend, quantized);
  }
  DepthCheck check;
  check.scene = scene.name;
  check.target = target;
  check.backend = backend;
  if (quantized) check.map_format = quantized->format;
  for (int j = 0; j < gpu.height; ++j) {
    for (int i = 0; i < gpu.width; ++i) {
      if (!truth.clear[std::size_t(j) * gpu.width + i]) continue;
      const float centre = truth.surface.at(i, j);
      ++check.texels;
      const double error = std::abs(double(gpu.at(i, j)) - centre);
      check.max_abs_error = std::max(check.max_abs_error, error);
      // Interpolated z carries float rounding; 1e-5 relative is ~100 ulps.
      // The rasterizer may round a unorm depth either way: one step.
      const double step = quantized
                              ? depth_step(quantized->format) *
                                    depth_per_unit(quantized->encoding, centre, quantized->range)
                              : 0.0;
      if (!(error <= 1e-5 * centre + step)) ++check.mismatched;
    }
  }
  check.pass = check.texels > 0 && check.mismatched == 0;
  return check;
}

Result<SceneFixture> prepare_scene(Engine& engine, SceneTruths& truths, const PassProgram& depth,
                                   Target target, const reference::Scene& scene,
                                   FloatImage receivers, DepthFormat map_format) {
  SceneFixture fixture;
  fixture.scene = scene;
  const float depth_scale = depth_scale_for(scene.far_z);
  fixture.params = shadow_params(
      scene.light,
      {scene.map_width, scene.map_height, scene.receivers_width, scene.receivers_height},
      depth_scale);
  const auto triangles = reference::triangles(scene);
  const MapEncoding encoding = depth.reflection.map_encoding.value_or(MapEncoding::linear);
  fixture.encoded = reference::encoded_depth(encoding, scene.light, depth_scale);
  // hlsl_dx9 reads its R32F target, the others the depth image.
  const bool reads_depth_image = traits(target).comparison_sampler;
  if (fixture.encoded && reads_depth_image) fixture.encoded->format = map_format;
  auto map = engine.render_depth(depth, triangles, scene.map_width, scene.map_height,
                                 fixture.params, fixture.map_format());
  if (!map) return map.error();
  fixture.map = *map;
  // A linear map's two images are the same; an encoded one's depth image is
  // the rasterizer's depth and its colour image the shader's encoding.
  auto stored = reads_depth_image ? engine.read_shadow_depth(**map) : engine.read_shadow_map(**map);
  if (!stored) return stored.error();
  fixture.linear_depth = linear_depth_of(*stored, fixture.encoded, depth_scale);
  fixture.normalized_depth = std::move(*stored);
  fixture.receivers = std::move(receivers);
  fixture.colour = reference::scene_colour(scene.receivers_width, scene.receivers_height);
  fixture.depth_truth = truths.depth(scene, scene.map_width, scene.map_height);
  fixture.depth_check =
      check_depth(*fixture.depth_truth, scene, target, fixture.linear_depth, "vulkan",
                  fixture.map_format() != DepthFormat::d32_float ? fixture.encoded : std::nullopt);
  fixture.depth_check.map_encoding = encoding;
  return fixture;
}

FloatImage linear_depth_of(const FloatImage& stored,
                           const std::optional<reference::EncodedDepth>& encoded,
                           float depth_scale) {
  FloatImage linear = stored;
  for (float& d : linear.data) {
    d = encoded ? float(decode_depth(encoded->encoding, d, encoded->range))
                : d / depth_scale;  // exact: a power of two
  }
  return linear;
}

Result<reference::ReferenceImage> reference_on_map(const Variant& variant,
                                                   const SceneFixture& fixture,
                                                   const FloatImage& stored,
                                                   const FloatImage& linear,
                                                   const reference::SamplingPrecision& precision,
                                                   const reference::ShaderLimits& limits) {
  if (fixture.encoded) {
    return reference::evaluate_image(variant, stored, *fixture.encoded, fixture.scene.light,
                                     fixture.receivers, precision, limits);
  }
  return reference::evaluate_image(variant, linear, fixture.scene.light, fixture.receivers,
                                   precision, limits);
}

}  // namespace penumbra
