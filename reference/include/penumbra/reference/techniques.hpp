// The CPU reference of every technique (docs/techniques.md), in double
// precision and independent of the shader sources.
#pragma once

#include "penumbra/model/model.hpp"
#include "penumbra/reference/light.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::reference {

// Receivers farther than this are evaluated at this depth (2^60): far enough
// to be behind any occluder a map can hold, near enough that the shaders'
// float32 products of two depths stay finite (docs/robustness.md).
inline constexpr double kMaxReceiverDepth = 1152921504606846976.0;

// A receiver: its shadow-map coordinates and linear light-view z; the pixel
// of the receivers image it is (column, row), by which a variant with the
// `rotation` key places its samples; and its plane's depth slope dz/du,
// dz/dv, which a `receiver_plane` variant adds to each sample's reference.
struct Query {
  double u = 0.0;
  double v = 0.0;
  double z = 0.0;
  int pixel_x = 0;
  int pixel_y = 0;
  double dz_du = 0.0;
  double dz_dv = 0.0;
};

// What one target's shader is held to where it changes results.
struct ShaderLimits {
  // traits(target).walk_step_limit: the cap on a min-max walk's steps
  // (0: none). A walk it stops returns what it reached (walk_step_bound()).
  int walk_steps = 0;
};

// The limits of `target`'s shaders (its traits).
ShaderLimits shader_limits(Target target);

struct Sample {
  double visibility = 1.0;  // in [0, 1]
  bool ambiguous = false;   // a point sample lies so close to a texel boundary that a
                            // GPU may legitimately read the other texel and differ
};

// Checks that `variant` carries what its technique needs (kernel, disks with
// as many points as the sample-count keys, traversal and max_nodes in range).
Status check_variant(const Variant& variant);

// Whether the reference of `technique` reads the min-max mip: minmax_pcf
// (for a capped walk; uncapped it counts texel by texel), backprojection
// and pcss_minmax.
bool reference_reads_mip(Technique technique);

// One receiver, as the shader of a target with `limits` computes it: in
// [0, 1] for any input. A receiver at or behind the light (z <= 0), or
// with a NaN depth, is lit (pcss and pcss_minmax: up to the near plane);
// one beyond kMaxReceiverDepth is taken there.
// `variant` must pass check_variant(); `mip` must be built from `map` (read
// where reference_reads_mip()).
Sample evaluate(const Variant& variant, const ShadowMapView& map, const MinMaxMip& mip,
                const LightParams& light, const Query& query,
                const SamplingPrecision& precision = {}, const ShaderLimits& limits = {});

// The same, building the mip first where the technique reads it: O(W H) per
// call for those, so for single receivers (evaluate_image builds it once).
Sample evaluate(const Variant& variant, const ShadowMapView& map, const LightParams& light,
                const Query& query, const SamplingPrecision& precision = {},
                const ShaderLimits& limits = {});

struct ReferenceImage {
  FloatImage visibility;  // 1 channel, the receivers' size
  FloatImage ambiguous;   // 1 channel: 1 where the pixel is ambiguous, else 0
};

// Every pixel of `receivers` (3 or 4 channels: u, v, z_r) against
// `shadow_map` (1 channel, linear z). Errors name what is wrong with the inputs.
Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& shadow_map,
                                      const LightParams& light, const FloatImage& receivers,
                                      const SamplingPrecision& precision = {},
                                      const ShaderLimits& limits = {});

}  // namespace penumbra::reference
