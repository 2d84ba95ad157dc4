// The per-technique references that technique_table.cpp assigns to each
// technique, and the point and PCF steps several of them share.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/sample_rotation.hpp"
#include "penumbra/reference/sampling.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference::detail {

// One point sample at (u, v): the nearest texel compared against z_ref, 1 lit
// or 0, ambiguous when a texel within the point window across a texel
// boundary compares differently (hard, and each of screen_blur's 9 compares).
Sample point_compare(const ShadowMapView& map, double u, double v, double z_ref,
                     const SamplingPrecision& precision);

// The mean of bilinear comparisons at texel offsets over a K x K grid.
double pcf_grid(const ShadowMapView& map, const Query& q, double z_ref, int kernel);

// PCSS's blocker search half-width in uv at receiver depth z (pcss and
// pcss_minmax): the light's footprint on the near plane seen from the
// receiver (similar triangles), L_uv (z - n) / z; a directional light's
// widens with the distance to the near plane alone, L_uv (z - n). In `Real`,
// the precision the caller's window is formed in (pcss_minmax: float, as
// its shader floors the window's edges).
template <typename Real>
Real pcss_search_width(const LightParams& light, Real z) {
  const Real depth = z - Real(light.near_plane);
  const Real light_size_uv = Real(light.light_size_uv());
  return light.orthographic() ? light_size_uv * depth : light_size_uv * depth / z;
}

// PCSS's filter radius in uv for a receiver at z_r and blockers at z_b (no
// nearer than the near plane): the parallel-plane penumbra
// (z_r - z_b) / z_b scaled to the near plane, or a directional light's
// slopes spread over z_r - z_b.
double pcss_filter_radius(const LightParams& light, double z_receiver, double z_blocker);

// The NVIDIA PCSS whitepaper's three steps.
Sample pcss(const ShadowMapView& map, const LightParams& light, const Query& q, double z_ref,
            const Disk& blocker_disk, const Disk& pcf_disk, const SamplingPrecision& precision);

// The mean of bilinear comparisons at uv + d * radius over the disk's points
// (pcf_poisson, and step 3 of pcss and pcss_minmax).
double poisson_pcf(const ShadowMapView& map, const Query& q, double z_ref,
                   const std::vector<Point2>& disk, double radius);

// `capped_steps`: the steps of the shader's walk where a target's cap stops
// it short (walk_step_bound()); then the result is what the walk reached.
Sample minmax_pcf(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                  const Query& q, const VariantKeys& keys, std::optional<int> capped_steps);

Sample backprojection(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                      const Query& q, const VariantKeys& keys, std::optional<int> capped_steps);

// backprojection's tolerance (docs/verification.md, "Tolerances"): the
// float32 error of its patches' edges where the receiver is not marked
// (kBackprojectionEdgeBudget), and 1e-4 for the float32 sum of the areas.
inline constexpr double kBackprojectionEdgeBudget = 2e-4;
inline constexpr double kBackprojectionTolerance = kBackprojectionEdgeBudget + 1e-4;

// Whether the float32 errors of the patch edges that backprojection's walk
// over `window` (at most `steps` steps) hands over may move the visibility
// by more than kBackprojectionEdgeBudget (Projector::area_error()).
bool area_edges_close(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                      const Query& q, const TexelRect& window, const VariantKeys& keys, int steps);

// The length of [lo, hi] inside [-half, half]: one axis of a projected
// patch inside the light.
double overlap(double lo, double hi, double half);

// backprojection's shader stopped after `steps` steps of its walk over
// `window` (brute_force: texels in row order): the visibility of the area
// it reached, ambiguous where one of the shader's float32 decisions that
// steer the walk lies too close to call.
Sample backprojection_capped(const ShadowMapView& map, const MinMaxMip& mip,
                             const LightParams& light, const Query& q, const TexelRect& window,
                             const VariantKeys& keys, int steps);

// What a back-projection walk takes as occluders: texels whose float depth
// is below the biased reference and in front of the receiver.
inline float occluder_limit(const LightParams& light, const Query& q) {
  return std::min(float_reference(q.z, light.bias), float(q.z));
}

// Whether an edge of backprojection_window() lies so close to a texel
// boundary that the shader's float32 floor may fall on the other side.
bool window_edges_close(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                        const Query& q);

// bitmask_backprojection: the shader's walk (backprojection_walk.hpp) sets
// the bits of the light samples each patch covers; 1 - set / N, ambiguous
// where a sample centre lies too close to a patch's edge to call and no
// other patch covers it, or where a close decision met a truncated walk.
Sample bitmask_backprojection(const ShadowMapView& map, const MinMaxMip& mip,
                              const LightParams& light, const Query& q, const VariantKeys& keys,
                              int steps);

// screen_blur's factor: the mean of 9 point_compare()s at (u + i / W,
// v + j / H), i, j in -1..1, ambiguous when any of them is.
Sample screen_blur_factor(const ShadowMapView& map, const Query& q, double z_ref,
                          const SamplingPrecision& precision);

Sample pcss_minmax(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                   const Query& q, const Disk& pcf_disk, const SamplingPrecision& precision);

// What check_variant() asks of a variant's parts (variant_checks.cpp); errors
// (bad_input) name the variant.
Status check_disk(const Variant& variant, const std::optional<Disk>& disk, const char* role,
                  const std::optional<int>& samples, const char* samples_key);
Status check_kernel(const Variant& variant, int max_kernel, bool odd);
Status check_traversal(const Variant& variant);
Status check_max_nodes(const Variant& variant);
Status check_blur(const Variant& variant);
Status check_light_bits(const Variant& variant);
Status check_rotation(const Variant& variant);

}  // namespace penumbra::reference::detail
