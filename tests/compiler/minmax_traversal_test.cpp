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

TEST(VariantHeader, MinmaxDefines) {
  const Variant minmax = variant_of(Technique::minmax_pcf, [](VariantKeys& k) { k.kernel = 12; });
  const std::string pcf = variant_header(&minmax, Target::hlsl_dx9);
  EXPECT_THAT(pcf, HasSubstr("#define KERNEL_SIZE 12\n"));
  EXPECT_THAT(pcf, HasSubstr("#define MINMAX_MAX_STEPS 224\n"));  // hlsl_dx9's cap
  EXPECT_THAT(variant_header(&minmax, Target::spirv),
              HasSubstr("#define MINMAX_MAX_STEPS " + std::to_string(316 + 78) + "\n"));
  EXPECT_THAT(pcf, ::testing::Not(HasSubstr("PENUMBRA_TRAVERSAL_BRUTE_FORCE")));

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

}  // namespace
}  // namespace penumbra
