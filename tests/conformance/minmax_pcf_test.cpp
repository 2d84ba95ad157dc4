// minmax_pcf on the device, for every target: the min-max traversal counts
// exactly what brute force counts, for kernels from 1 to 128 on every scene
// (one of them a 250 x 190 map, so partial nodes at the edges are crossed),
// bit for bit against the CPU reference and against the GPU's own brute
// force; and on large flat regions it reads far fewer texels than the K^2
// brute force does. Each target's map and mip come from its own passes. A
// target that caps the walk's steps (hlsl_dx9) builds only the kernels whose
// walk fits the cap (inexact_walk()), so it is exact too.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

constexpr int kKernels[] = {1, 7, 8, 12, 45, 64, 128};

// Whether `target` builds minmax_pcf with `kernel` (and `traversal`).
bool builds(Target target, int kernel, const char* traversal = nullptr) {
  Variant variant;
  variant.technique = Technique::minmax_pcf;
  variant.keys.kernel = kernel;
  if (traversal) variant.keys.traversal = traversal;
  return inexact_walk(variant, target).empty();
}

// The kernel whose traversal is also run by brute force: 45, or 8 where the
// target's cap allows no more.
int brute_force_kernel(Target target) {
  return builds(target, 45, "brute_force") ? 45 : 8;
}

// The traversal variants `target` builds.
std::vector<std::string> traversals(Target target) {
  std::vector<std::string> out;
  for (int kernel : kKernels) {
    if (builds(target, kernel)) out.push_back("minmax_pcf_k" + std::to_string(kernel));
  }
  return out;
}

// The variants for one target (a library per target: a test runs one).
std::string manifest(Target target) {
  std::string kernels;
  for (int kernel : kKernels) {
    if (builds(target, kernel)) kernels += (kernels.empty() ? "" : ", ") + std::to_string(kernel);
  }
  return R"({
  "schema": 1,
  "targets": [")" +
         std::string(to_string(target)) + R"("],
  "sets": [
    {"technique": "minmax_pcf", "kernel": [)" +
         kernels + R"(]},
    {"technique": "minmax_pcf", "kernel": )" +
         std::to_string(brute_force_kernel(target)) + R"(, "traversal": "brute_force"}
  ]})";
}

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

// A scene's map rendered by the library's depth pass, its mip built by the
// library's minmax passes, and what the reference needs.
struct RenderedScene {
  reference::Scene scene;
  ParamBlock params;
  std::shared_ptr<ShadowMap> map;
  FloatImage linear_depth;
  FloatImage receivers;
};

class MinmaxPcfTest : public ::testing::TestWithParam<Target> {
 protected:
  static void SetUpTestSuite() {
    auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
    ASSERT_TRUE(engine) << engine.error().to_string();
    engine_ = engine->release();
  }

  static void TearDownTestSuite() {
    delete engine_;
    engine_ = nullptr;
    libraries_.clear();
  }

  // The parameter's library, built on first use.
  void SetUp() override {
    ASSERT_NE(engine_, nullptr);
    const Target target = GetParam();
    if (libraries_.count(target)) return;
    auto parsed = parse_manifest(manifest(target), "minmax_pcf_test");
    ASSERT_TRUE(parsed) << parsed.error().to_string();
    auto variants = expand(*parsed);
    ASSERT_TRUE(variants) << variants.error().to_string();
    auto built = TemporaryLibrary::build(std::move(*variants));
    ASSERT_TRUE(built) << built.error().to_string();
    libraries_[target] = std::move(*built);
  }

  static const Library& library() { return libraries_.at(GetParam())->library(); }

  static const LibraryVariant& variant(const std::string& name) {
    const LibraryVariant* found = library().find(name);
    EXPECT_NE(found, nullptr) << name;
    return *found;
  }

  static PassProgram program(const std::string& name, PassKind pass) {
    auto loaded = load_executable(library(), variant(name), pass, GetParam());
    EXPECT_TRUE(loaded) << loaded.error().to_string();
    return loaded ? loaded->program : PassProgram{};
  }

  static RenderedScene render(const reference::Scene& scene) {
    RenderedScene out;
    out.scene = scene;
    const float depth_scale = depth_scale_for(scene.far_z);
    out.params = shadow_params(
        scene.light,
        {scene.map_width, scene.map_height, scene.receivers_width, scene.receivers_height},
        depth_scale);
    auto map = engine_->render_depth(program("minmax_pcf_k7", PassKind::depth),
                                     reference::triangles(scene), scene.map_width, scene.map_height,
                                     out.params);
    EXPECT_TRUE(map) << map.error().to_string();
    if (!map) return out;
    out.map = *map;
    auto built =
        engine_->build_minmax(*out.map, program("minmax_pcf_k7", PassKind::minmax_init),
                              program("minmax_pcf_k7", PassKind::minmax_reduce), out.params);
    EXPECT_TRUE(built) << built.error().to_string();
    auto normalized = engine_->read_shadow_map(*out.map);
    EXPECT_TRUE(normalized) << normalized.error().to_string();
    if (!normalized) return out;
    out.linear_depth = std::move(*normalized);
    for (float& d : out.linear_depth.data) d /= depth_scale;  // exact: a power of two
    out.receivers = reference::receivers(scene, scene.receivers_width, scene.receivers_height);
    return out;
  }

  static QueryOutput query(const std::string& name, const RenderedScene& rendered) {
    auto output = engine_->run_query_output(program(name, PassKind::query), *rendered.map,
                                            rendered.receivers, rendered.params);
    EXPECT_TRUE(output) << name << ": " << output.error().to_string();
    return output ? std::move(*output) : QueryOutput{};
  }

  static inline Engine* engine_ = nullptr;
  static inline std::map<Target, std::unique_ptr<TemporaryLibrary>> libraries_;
};

TEST_P(MinmaxPcfTest, TraversalEqualsBruteForceBitForBitOnEveryScene) {
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    const RenderedScene rendered = render(scene);
    ASSERT_NE(rendered.map, nullptr) << scene.name;
    std::map<std::string, QueryOutput> gpu;
    std::vector<std::string> names = traversals(GetParam());
    const std::string compared = "minmax_pcf_k" + std::to_string(brute_force_kernel(GetParam()));
    names.push_back(compared + "_brute_force");
    for (const std::string& name : names) {
      const QueryOutput& output = gpu[name] = query(name, rendered);
      auto cpu =
          reference::evaluate_image(variant(name).variant, rendered.linear_depth, scene.light,
                                    rendered.receivers, {}, reference::shader_limits(GetParam()));
      ASSERT_TRUE(cpu) << cpu.error().to_string();
      ASSERT_EQ(output.visibility.pixel_count(), cpu->visibility.pixel_count()) << name;
      std::size_t differing = 0, partial = 0;
      for (std::size_t p = 0; p < output.visibility.pixel_count(); ++p) {
        if (!same_bits(output.visibility.data[p], cpu->visibility.data[p])) ++differing;
        if (cpu->visibility.data[p] > 0.0f && cpu->visibility.data[p] < 1.0f) ++partial;
      }
      EXPECT_EQ(differing, 0u) << name << " on " << scene.name << " (" << scene.map_width << "x"
                               << scene.map_height << ")";
      // K = 1 is hard shadows; every other kernel must see penumbrae.
      if (name != "minmax_pcf_k1") {
        EXPECT_GT(partial, 100u) << name << " on " << scene.name;
      }
    }
    const QueryOutput& tree = gpu.at(compared);
    const QueryOutput& brute = gpu.at(compared + "_brute_force");
    ASSERT_EQ(tree.visibility.pixel_count(), brute.visibility.pixel_count());
    std::size_t differing = 0;
    for (std::size_t p = 0; p < tree.visibility.pixel_count(); ++p) {
      if (!same_bits(tree.visibility.data[p], brute.visibility.data[p])) ++differing;
    }
    EXPECT_EQ(differing, 0u) << compared << " against brute force on " << scene.name;
  }
}

// Half the map under one big occluder, half open: almost every window is
// flat, so the traversal stops at a few large nodes.
TEST_P(MinmaxPcfTest, FlatRegionsReadFarFewerTexelsThanTheKernel) {
  if (!builds(GetParam(), 64)) GTEST_SKIP() << "no K = 64 on " << to_string(GetParam());
  reference::Scene scene;
  scene.name = "flat_halves";
  // u < 0.5 at z = 12: x < 0 with the NVIDIA PCSS whitepaper's light.
  scene.occluders = {{-6.0, -6.0, 0.0, 6.0, 12.0}};
  scene.plane_z0 = 16.0;
  scene.receivers_width = 128;
  scene.receivers_height = 128;
  const RenderedScene rendered = render(scene);
  ASSERT_NE(rendered.map, nullptr);
  const QueryOutput tree = query("minmax_pcf_k64", rendered);
  ASSERT_EQ(tree.texel_reads.pixel_count(), 128u * 128u);
  double sum = 0.0, lit = 0.0, shadowed = 0.0;
  for (std::size_t p = 0; p < tree.texel_reads.pixel_count(); ++p) {
    sum += tree.texel_reads.data[p];
    lit += tree.visibility.data[p] == 1.0f ? 1.0 : 0.0;
    shadowed += tree.visibility.data[p] == 0.0f ? 1.0 : 0.0;
  }
  // Both kinds of flat region are large (texels outside the map do not
  // occlude, so windows reaching past its edges are not fully shadowed).
  EXPECT_GT(lit, 0.3 * 128 * 128);
  EXPECT_GT(shadowed, 0.15 * 128 * 128);
  const double mean = sum / (128.0 * 128.0);
  RecordProperty("mean_texel_reads_k64", std::to_string(mean));
  EXPECT_LT(mean, 64.0 * 64.0 / 20.0) << "mean texel reads " << mean << " for K^2 = 4096";
  EXPECT_GE(mean, 1.0);
}

INSTANTIATE_TEST_SUITE_P(AllTargets, MinmaxPcfTest, ::testing::ValuesIn(kAllTargets),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra::testing
