// The CPU reference of every technique (docs/techniques.md), in double
// precision and independent of the shader sources.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/model/model.hpp"
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

  bool operator==(const ShaderLimits&) const = default;
};

// The limits of `target`'s shaders (its traits).
ShaderLimits shader_limits(Target target);

// Why a receiver is ambiguous: a float32 or sampling decision of the shader
// lies so close to call that a correct GPU may take the other side and
// differ. One bit per reason, a receiver marked for several holding their
// sum; these are the codes `penumbra eval --ambiguous` writes
// (docs/verification.md, "The ambiguity rule").
enum class Ambiguity : std::uint16_t {
  none = 0,
  // A point sample within the point window of a texel boundary whose two
  // sides compare differently: hard, each of screen_blur's nine compares,
  // pcss's blocker search, a back-projection's point light.
  texel_boundary = 1,
  // A sample that the `rotation` key shifts within 1e-6 of the seam of the
  // square's torus (placed_disk()).
  rotation_seam = 2,
  // pcss_minmax: an edge of the blocker-search window within the point
  // window of a texel boundary, where the other side moves the result past
  // the tolerance.
  search_window_edge = 4,
  // backprojection under a step cap: the walk stopped short after a
  // decision that steers it (a node reaching the light, an edge of the
  // culling window) lay within float32's reach of the other answer.
  walk_decision = 8,
  // bitmask_backprojection: a light sample within edge_error() of a patch's
  // edge that no other patch surely covers.
  light_sample_edge = 16,
  // bitmask_backprojection: the walk stopped short by its step bound or
  // max_nodes.
  walk_truncated = 32,
  // receiver_plane: the depth slopes a GPU may derive give results further
  // apart than the tolerance.
  depth_slope = 64,
  // backprojection: the float32 errors of its patches' edges inside the
  // light (under any evaluation a compiler may choose) may move the
  // visibility by more than 2e-4, all but 1e-4 of its tolerance.
  area_edges = 128,
  // A map in a hardware encoding: a texel's depth lies within tie_margin()
  // of the receiver's, so a shader's float32 encoding of the receiver may
  // compare it either way, and the two ways differ by more than half the
  // tolerance.
  depth_tie = 256,
  // A receiver the GPU rebuilt in float32 (the deferred pass, from a
  // camera's depth): its float32 rebuilding moves the result by more than
  // half the tolerance.
  receiver_rounding = 512,
  // No receiver at the pixel (an engine's sky, marked by eval's
  // --no-receiver mask): shaded as a NaN receiver, and nothing to compare.
  no_receiver = 1024,
};

constexpr Ambiguity operator|(Ambiguity a, Ambiguity b) {
  return Ambiguity(std::uint16_t(a) | std::uint16_t(b));
}

constexpr Ambiguity& operator|=(Ambiguity& a, Ambiguity b) {
  return a = a | b;
}

// Each reason in code order, with a few words for `penumbra eval --help`.
struct AmbiguityReason {
  Ambiguity reason;
  const char* summary;
};
inline constexpr AmbiguityReason kAmbiguityReasons[] = {
    {Ambiguity::texel_boundary, "a point sample at a texel boundary"},
    {Ambiguity::rotation_seam, "a rotated sample on the square's seam"},
    {Ambiguity::search_window_edge, "pcss_minmax's search window edge at a texel boundary"},
    {Ambiguity::walk_decision, "a capped backprojection walk's close decision"},
    {Ambiguity::light_sample_edge, "a bitmask light sample at a patch edge"},
    {Ambiguity::walk_truncated, "a bitmask walk stopped short"},
    {Ambiguity::depth_slope, "receiver_plane's depth slopes disagree"},
    {Ambiguity::area_edges, "backprojection's patch edges may move the area too far"},
    {Ambiguity::depth_tie, "an encoded map's texel at the receiver's depth"},
    {Ambiguity::receiver_rounding, "a rebuilt receiver's float32 rounding moves the result"},
    {Ambiguity::no_receiver, "no receiver at the pixel (--no-receiver)"},
};

// `reason` where `marked`, else none.
constexpr Ambiguity ambiguous_if(bool marked, Ambiguity reason) {
  return marked ? reason : Ambiguity::none;
}

struct Sample {
  double visibility = 1.0;                // in [0, 1]
  Ambiguity ambiguous = Ambiguity::none;  // why a GPU may legitimately differ
};

// Checks that `variant` carries what its technique needs (kernel, disks with
// as many points as the sample-count keys, traversal and max_nodes in range).
Status check_variant(const Variant& variant);

// The visibility `variant`'s passes end in, from `visibility`, the image
// its query gives (evaluate_image()'s) over `receivers`: its technique's
// screen passes applied (screen_blur's blur), or `visibility` itself where
// the query's image is the result.
FloatImage screen_visibility(const Variant& variant, FloatImage visibility,
                             const FloatImage& receivers);
// Whether screen_visibility() changes `technique`'s image.
bool filters_screen(Technique technique);

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
  FloatImage ambiguous;   // 1 channel: the pixel's Ambiguity bits, 0 where decided
  // 1 channel each: the visibility's range over the maps a GPU may in effect
  // compare against (an encoded map's depths moved by their tie margin);
  // the visibility itself for a linear map.
  FloatImage low;
  FloatImage high;
};

// Every pixel of `receivers` (3 or 4 channels: u, v, z_r) against
// `shadow_map` (1 channel, linear z). Errors name what is wrong with the inputs.
Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& shadow_map,
                                      const LightParams& light, const FloatImage& receivers,
                                      const SamplingPrecision& precision = {},
                                      const ShaderLimits& limits = {});

// The same against `stored`, a map as a GPU holds it in `encoded`'s
// encoding: the visibility of the exactly decoded
// depths, with depth_tie where moving every depth tie_margin() towards and
// away from the light changes the result by more than half the tolerance.
// Errors: bad_input also for a technique whose reference reads the min-max
// mip (built from linear depth).
Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& stored,
                                      const EncodedDepth& encoded, const LightParams& light,
                                      const FloatImage& receivers,
                                      const SamplingPrecision& precision = {},
                                      const ShaderLimits& limits = {});

// The visibility alone of `pixels` (row-major indices into each image of
// `receivers`, all of one size) against `map`, every other pixel 0: one
// image per receivers image, for a check that needs the reference at a few
// pixels under several receivers, without the depth_tie evaluations an
// encoded map's evaluate_image() makes. The mip, where the technique reads
// it, is built once for all of them. Errors: as evaluate_image()'s, and
// bad_input for images of different sizes or an index outside them.
Result<std::vector<FloatImage>> evaluate_visibility(
    const Variant& variant, const ShadowMapView& map, const LightParams& light,
    std::span<const FloatImage> receivers, std::span<const std::size_t> pixels,
    const SamplingPrecision& precision = {}, const ShaderLimits& limits = {});

}  // namespace penumbra::reference
