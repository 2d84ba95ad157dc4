// The min-max traversal's compile-time bounds and the defines a variant
// header gives the walks. (The CPU simulation of the walk that proves the
// bound is tests/reference/minmax_cursor_test.cpp.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "glsl/variant_header.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {
namespace {

using ::testing::HasSubstr;

TEST(MinmaxTraversal, MaxVisitsFollowsTheFormula) {
  EXPECT_EQ(minmax_max_visits(1), 4);
  EXPECT_EQ(minmax_max_visits(2), 4);
  // K = 3: levels 1..1, (floor(2 / 2) + 2)^2 = 9 nodes: 4 + 4 * 9.
  EXPECT_EQ(minmax_max_visits(3), 40);
  // K = 12: levels 1..4 with 7, 4, 3, 2 nodes per axis.
  EXPECT_EQ(minmax_max_visits(12), 4 + 4 * (49 + 16 + 9 + 4));
  EXPECT_EQ(minmax_max_visits(128), 22892);
}

// A step stands on a node or rises from the children of a descended node.
TEST(MinmaxTraversal, MaxStepsAddOneRiseForEveryFourVisitsPastTheRoots) {
  EXPECT_EQ(minmax_max_steps(2), 4);
  EXPECT_EQ(minmax_max_steps(3), 40 + 9);
  EXPECT_EQ(minmax_max_steps(128), 22892 + 5722);
}

// The variant's own bound, or a target's cap where that is lower.
TEST(MinmaxTraversal, WalkStepBoundIsCappedByTheTarget) {
  Variant pcf;
  pcf.technique = Technique::minmax_pcf;
  pcf.keys.kernel = 64;
  EXPECT_EQ(walk_step_bound(pcf), minmax_max_steps(64));
  EXPECT_EQ(walk_step_bound(pcf, 224), 224);
  pcf.keys.traversal = std::string(kBruteForceTraversal);
  EXPECT_EQ(walk_step_bound(pcf), 64 * 64);
  pcf.keys.kernel = 8;
  EXPECT_EQ(walk_step_bound(pcf, 224), 64);
  Variant back;
  back.technique = Technique::backprojection;
  EXPECT_EQ(walk_step_bound(back), 2 * kDefaultMaxNodes);
  back.keys.traversal = std::string(kBruteForceTraversal);
  EXPECT_EQ(walk_step_bound(back, 224), 224);
  Variant hard;
  EXPECT_FALSE(walk_step_bound(hard, 224).has_value());
}

// A variant of `technique` with the keys `set` gives.
template <typename Set>
Variant variant_of(Technique technique, Set set) {
  Variant v;
  v.technique = technique;
  set(v.keys);
  v.name = variant_name(technique, v.keys);
  return v;
}

// minmax_pcf is exact only where its worst-case walk fits the target's cap:
// on hlsl_dx9 up to K = 8 (194 steps; K = 9 may take 309), up to K = 14
// with brute force (196 texels).
TEST(MinmaxTraversal, InexactWalkWhereTheWorstCaseExceedsTheCap) {
  EXPECT_EQ(minmax_max_steps(8), 194);
  EXPECT_EQ(minmax_max_steps(9), 309);
  auto pcf = [](int kernel, bool brute_force) {
    return variant_of(Technique::minmax_pcf, [&](VariantKeys& k) {
      k.kernel = kernel;
      if (brute_force) k.traversal = std::string(kBruteForceTraversal);
    });
  };
  for (Target target : kAllTargets) {
    const bool capped = target == Target::hlsl_dx9;
    EXPECT_EQ(inexact_walk(pcf(8, false), target), "");
    EXPECT_EQ(inexact_walk(pcf(14, true), target), "");
    EXPECT_EQ(inexact_walk(pcf(9, false), target).empty(), !capped);
    EXPECT_EQ(inexact_walk(pcf(15, true), target).empty(), !capped);
    EXPECT_EQ(inexact_walk(pcf(128, false), target).empty(), !capped);
  }
  EXPECT_EQ(inexact_walk(pcf(16, false), Target::hlsl_dx9),
            "minmax_pcf_k16 cannot count exactly on hlsl_dx9: its walk may take 599 steps, and "
            "hlsl_dx9 stops every walk after 224 (ps_3_0 guarantees only 65,535 executed "
            "instructions); the largest kernel that fits is 8");
  EXPECT_EQ(inexact_walk(pcf(16, true), Target::hlsl_dx9),
            "minmax_pcf_k16_brute_force cannot count exactly on hlsl_dx9: its walk may take 256 "
            "steps (a texel each), and hlsl_dx9 stops every walk after 224 (ps_3_0 guarantees "
            "only 65,535 executed instructions); the largest kernel that fits is 14 with "
            "traversal brute_force");
  // Every other technique keeps what it promises under the cap.
  const Variant back = variant_of(Technique::backprojection, [](VariantKeys&) {});
  EXPECT_EQ(inexact_walk(back, Target::hlsl_dx9), "");
}

TEST(VariantHeader, MinmaxDefines) {
  const Variant minmax = variant_of(Technique::minmax_pcf, [](VariantKeys& k) { k.kernel = 12; });
  const std::string pcf = variant_header(&minmax, Target::spirv);
  EXPECT_THAT(pcf, HasSubstr("#define KERNEL_SIZE 12\n"));
  EXPECT_THAT(pcf, HasSubstr("#define MINMAX_MAX_STEPS " + std::to_string(316 + 78) + "\n"));
  EXPECT_THAT(pcf, ::testing::Not(HasSubstr("PENUMBRA_TRAVERSAL_BRUTE_FORCE")));
  // Within hlsl_dx9's cap: the walk's own bound.
  const Variant small = variant_of(Technique::minmax_pcf, [](VariantKeys& k) { k.kernel = 8; });
  EXPECT_THAT(variant_header(&small, Target::hlsl_dx9),
              HasSubstr("#define MINMAX_MAX_STEPS 194\n"));

  const Variant brute = variant_of(Technique::backprojection, [](VariantKeys& k) {
    k.traversal = std::string(kBruteForceTraversal);
  });
  const std::string back = variant_header(&brute, Target::spirv);
  EXPECT_THAT(back, HasSubstr("#define PENUMBRA_TRAVERSAL_BRUTE_FORCE 1\n"));
  EXPECT_THAT(back, HasSubstr("#define BACKPROJECTION_MAX_NODES 16384\n"));
  EXPECT_THAT(back, HasSubstr("#define BACKPROJECTION_MAX_STEPS 16384\n"));

  const Variant bounded =
      variant_of(Technique::backprojection, [](VariantKeys& k) { k.max_nodes = 4096; });
  EXPECT_THAT(variant_header(&bounded, Target::spirv),
              HasSubstr("#define BACKPROJECTION_MAX_NODES 4096\n"));
}

// backprojection's min-max walk finishes from coarser levels where the
// target's cap binds, and only there.
TEST(VariantHeader, BackprojectionFinishesCoarseWhereTheCapBinds) {
  constexpr const char* kFinish = "#define BACKPROJECTION_FINISH_COARSE 1\n";
  const Variant walk = variant_of(Technique::backprojection, [](VariantKeys&) {});
  EXPECT_THAT(variant_header(&walk, Target::hlsl_dx9), HasSubstr(kFinish));
  EXPECT_THAT(variant_header(&walk, Target::hlsl_dx9),
              HasSubstr("#define BACKPROJECTION_MAX_STEPS 224\n"));
  EXPECT_THAT(variant_header(&walk, Target::hlsl_dx11), ::testing::Not(HasSubstr(kFinish)));
  // max_nodes 64: 128 steps, under the cap.
  const Variant bounded =
      variant_of(Technique::backprojection, [](VariantKeys& k) { k.max_nodes = 64; });
  EXPECT_THAT(variant_header(&bounded, Target::hlsl_dx9), ::testing::Not(HasSubstr(kFinish)));
  // Brute force has no coarser level to finish from: it stops.
  const Variant brute = variant_of(Technique::backprojection, [](VariantKeys& k) {
    k.traversal = std::string(kBruteForceTraversal);
  });
  EXPECT_THAT(variant_header(&brute, Target::hlsl_dx9), ::testing::Not(HasSubstr(kFinish)));
}

}  // namespace
}  // namespace penumbra
