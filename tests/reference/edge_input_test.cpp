// Every default variant's reference on edge inputs (docs/robustness.md,
// "Edge inputs"): receivers at or before the near plane, NaN, infinite or
// beyond float range; uv outside [0, 1]; map depths 0, inf and NaN; a point
// light and a huge one. Each result is in [0, 1], and the defined cases
// give what the semantics say.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "edge_inputs.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::testing {
namespace {

using reference::Query;

class EdgeInputs : public ::testing::TestWithParam<std::string> {
 protected:
  const Variant& variant() const { return *find_default_variant(GetParam()); }

  // The receiver's visibility on `map`, uncapped and with Direct3D 9's
  // capped walk, each checked to be in [0, 1]; returns the uncapped one.
  double visibility(const FloatImage& map, const LightParams& light, const Query& q,
                    const std::string& what) const {
    const reference::ShadowMapView view(map);
    double uncapped = 0.0;
    for (Target target : {Target::spirv, Target::hlsl_dx9}) {
      const double v =
          reference::evaluate(variant(), view, light, q, {}, reference::shader_limits(target))
              .visibility;
      EXPECT_TRUE(v >= 0.0 && v <= 1.0) << what << " on " << to_string(target) << ": " << v;
      if (target == Target::spirv) uncapped = v;
    }
    return uncapped;
  }
};

TEST_P(EdgeInputs, EveryResultIsInRangeAndNeverNaN) {
  for (const EdgeMap& map : edge_maps()) {
    for (const EdgeLight& light : edge_lights()) {
      for (const Query& q : edge_queries(light.light)) {
        visibility(map.depth, light.light, q, describe(map, light, q));
      }
    }
  }
}

// pcss and pcss_minmax also up to the near plane, where their search width
// L_uv (z_r - n) / z_r is 0 or negative.
TEST_P(EdgeInputs, ReceiversAtOrBehindTheLightOrNaNAreLit) {
  const bool near_lit =
      variant().technique == Technique::pcss || variant().technique == Technique::pcss_minmax;
  for (const EdgeMap& map : edge_maps()) {
    for (const EdgeLight& light : edge_lights()) {
      const double n = light.light.near_plane;
      std::vector<double> lit = {std::numeric_limits<double>::quiet_NaN(),
                                 -std::numeric_limits<double>::infinity(), -5.0, 0.0};
      if (near_lit) lit.insert(lit.end(), {1e-30, n / 2, n});
      for (double z : lit) {
        for (const auto& uv : edge_uvs()) {
          const Query q{uv[0], uv[1], z};
          EXPECT_EQ(visibility(map.depth, light.light, q, describe(map, light, q)), 1.0)
              << describe(map, light, q);
        }
      }
    }
  }
}

TEST_P(EdgeInputs, FarReceiversAreTakenAtTheDepthLimit) {
  for (const EdgeMap& map : edge_maps()) {
    for (const EdgeLight& light : edge_lights()) {
      for (const auto& uv : edge_uvs()) {
        const Query limit{uv[0], uv[1], reference::kMaxReceiverDepth};
        const double at_limit = visibility(map.depth, light.light, limit, "limit");
        for (double z : {1.7e38, double(std::numeric_limits<float>::max()),
                         std::numeric_limits<double>::infinity()}) {
          const Query q{uv[0], uv[1], z};
          EXPECT_EQ(visibility(map.depth, light.light, q, describe(map, light, q)), at_limit)
              << describe(map, light, q);
        }
      }
    }
  }
}

TEST_P(EdgeInputs, NaNTexelsOccludeNothing) {
  const FloatImage nan_map = uniform_map(std::numeric_limits<float>::quiet_NaN());
  const FloatImage inf_map = uniform_map(std::numeric_limits<float>::infinity());
  for (const EdgeLight& light : edge_lights()) {
    for (const Query& q : edge_queries(light.light)) {
      EXPECT_EQ(visibility(nan_map, light.light, q, "NaN map"), 1.0)
          << q.u << " " << q.v << " " << q.z;
      EXPECT_EQ(visibility(inf_map, light.light, q, "inf map"), 1.0)
          << q.u << " " << q.v << " " << q.z;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Default, EdgeInputs, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
