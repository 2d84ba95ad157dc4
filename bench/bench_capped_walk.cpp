// penumbra_bench_capped: backprojection where hlsl_dx9's cap on the walk's
// steps binds (docs/targets.md, "Executed instructions: the step cap"). On
// 512 x 512 maps of random occluders and on the report's stage, the CPU
// reference of the hlsl_dx9 shader (its walk finished from coarser levels)
// against the uncapped one every other target runs, and on the stage both
// against the exact area light. verify holds the GPU runs to these
// references, so they are what the shaders give.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "penumbra/reference/exact_visibility.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra {
namespace {

// `count` rectangles, each side `lo`..`hi` texels, at depths zlo..zhi over a
// receiver plane at depth `ground`, on a size x size map.
FloatImage random_occluders(int size, int count, int lo, int hi, double zlo, double zhi,
                            double ground, unsigned seed) {
  FloatImage map(size, size, 1, float(ground));
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> corner(0, size - 1), side(lo, hi);
  std::uniform_real_distribution<double> depth(zlo, zhi);
  for (int n = 0; n < count; ++n) {
    const int x0 = corner(random), y0 = corner(random), w = side(random), h = side(random);
    const float z = float(depth(random));
    for (int y = y0; y < std::min(size, y0 + h); ++y) {
      for (int x = x0; x < std::min(size, x0 + w); ++x) map.at(x, y) = std::min(map.at(x, y), z);
    }
  }
  return map;
}

struct Errors {
  double sum = 0.0, max = 0.0;
  long count = 0;
  void add(double error) {
    sum += error;
    max = std::max(max, error);
    ++count;
  }
  double mean() const { return count ? sum / double(count) : 0.0; }
};

// hlsl_dx9's reference and the uncapped one over `receivers`; `exact` and
// `measured` (the stage) add the penumbra error of each against the truth.
int measure(const std::string& name, const FloatImage& map, const LightParams& light,
            const FloatImage& receivers, const FloatImage* exact = nullptr,
            const std::vector<bool>* measured = nullptr) {
  const Variant variant{"backprojection", Technique::backprojection, {}, {}, {}, {}, {}};
  auto dx9 = reference::evaluate_image(variant, map, light, receivers, {},
                                       reference::shader_limits(Target::hlsl_dx9));
  auto whole = reference::evaluate_image(variant, map, light, receivers, {},
                                         reference::shader_limits(Target::hlsl_dx11));
  if (!dx9 || !whole) {
    std::fprintf(stderr, "%s\n", (dx9 ? whole.error() : dx9.error()).to_string().c_str());
    return 1;
  }
  Errors all, differing, penumbra_dx9, penumbra_whole;
  for (std::size_t p = 0; p < receivers.pixel_count(); ++p) {
    if (measured && !(*measured)[p]) continue;
    const double a = dx9->visibility.data[p], b = whole->visibility.data[p];
    all.add(std::abs(a - b));
    if (std::abs(a - b) > 1e-6) differing.add(std::abs(a - b));
    if (exact && exact->data[p] > 1e-9 && exact->data[p] < 1.0 - 1e-9) {
      penumbra_dx9.add(std::abs(a - exact->data[p]));
      penumbra_whole.add(std::abs(b - exact->data[p]));
    }
  }
  std::printf("%-8s %6ld of %6ld pixels differ; |hlsl_dx9 - uncapped| mean %.4f, max %.4f",
              name.c_str(), differing.count, all.count, all.mean(), all.max);
  if (exact) {
    std::printf("; penumbra error vs exact: hlsl_dx9 %.4f, uncapped %.4f", penumbra_dx9.mean(),
                penumbra_whole.mean());
  }
  std::printf("\n");
  return 0;
}

int run() {
  // The report's light over a receiver plane at z = 16, a 128 x 128 grid of
  // receivers on it.
  const reference::Stage stage = reference::report_stage();
  reference::Scene plane;
  plane.plane_z0 = 16.0;
  const FloatImage receivers = reference::receivers(plane, 128, 128);
  const LightParams& light = stage.scene.light;
  int failed =
      measure("boxes", random_occluders(512, 400, 4, 48, 8.0, 15.5, 16.0, 1), light, receivers);
  failed |=
      measure("foliage", random_occluders(512, 20000, 1, 4, 8.0, 15.5, 16.0, 2), light, receivers);
  // The stage as the report pictures it, on the ray-cast map.
  const reference::Scene& scene = stage.scene;
  const reference::StageView view =
      reference::view(stage, scene.receivers_width, scene.receivers_height);
  std::vector<bool> measured(view.surfaces.size());
  for (std::size_t p = 0; p < measured.size(); ++p) {
    measured[p] = reference::receives_light(view.surfaces[p]);
  }
  const FloatImage exact = reference::exact_visibility_image(scene, view);
  failed |= measure(
      "stage", reference::ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z),
      light, view.receivers, &exact, &measured);
  return failed;
}

}  // namespace
}  // namespace penumbra

int main() {
  return penumbra::run();
}
