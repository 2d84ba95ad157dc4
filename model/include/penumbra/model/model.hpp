// The data model shared by the compiler, the reference, the engines and
// verify: techniques, targets, Poisson disks and variants.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "penumbra/model/pass.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

enum class Technique {
  hard,
  pcf_grid,
  pcf_poisson,
  pcss,
  minmax_pcf,
  backprojection,
  pcss_minmax,
  screen_blur,
  bitmask_backprojection,
};
enum class Target { spirv, glsl450, glsl330, essl300, hlsl_dx11, hlsl_dx10, hlsl_dx9 };

inline constexpr std::array kAllTechniques = {
    Technique::hard,        Technique::pcf_grid,    Technique::pcf_poisson,
    Technique::pcss,        Technique::minmax_pcf,  Technique::backprojection,
    Technique::pcss_minmax, Technique::screen_blur, Technique::bitmask_backprojection};
inline constexpr std::array kAllTargets = {Target::spirv,   Target::glsl450,   Target::glsl330,
                                           Target::essl300, Target::hlsl_dx11, Target::hlsl_dx10,
                                           Target::hlsl_dx9};

std::string_view to_string(Technique technique);
std::string_view to_string(Target target);
std::optional<Technique> parse_technique(std::string_view name);
std::optional<Target> parse_target(std::string_view name);
// "hard, pcf_grid, ..." for messages that list what is allowed.
std::string allowed_techniques();
std::string allowed_targets();

// Whether the technique reads the min-max depth mip (Dmitriev 2007), so
// its variants need the mip build passes (describe(technique).reads_minmax).
bool uses_minmax_mip(Technique technique);

// Largest sample count / kernel size any variant may use.
inline constexpr int kMaxSamples = 128;

// The most variants a manifest may expand to (its "max_variants" at most)
// and a library's index.json may hold (docs/manifest.md, "Limits").
inline constexpr int kMaxVariants = 1000000;

// The one value of the `traversal` key: read every texel of the window
// instead of descending the min-max mip (minmax_pcf, backprojection).
inline constexpr std::string_view kBruteForceTraversal = "brute_force";

// bitmask_backprojection's `light_bits` N: the light is sampled by a
// sqrt(N) x sqrt(N) grid, one bit per sample, at most 32 bits per row.
inline constexpr std::array kAllowedLightBits = {16, 64, 256, 1024};
// "16, 64, 256, 1024" for messages.
std::string allowed_light_bits();
// sqrt(N) for an allowed N.
int light_grid_side(int light_bits);

// backprojection's `max_nodes`: the most nodes one query visits.
inline constexpr int kDefaultMaxNodes = 16384;  // when the key is unset
inline constexpr int kMaxMaxNodes = 1048576;

// screen_blur's `blur_radius` R: taps -R..R per blur pass ("Soft-Edged Shadows").
inline constexpr int kMaxBlurRadius = 32;
// screen_blur with depth_aware: a tap is dropped when its receiver z differs
// from the centre's by more than this fraction of the centre's z.
inline constexpr float kBlurDepthTolerance = 0.02f;

using Point2 = std::array<float, 2>;

// The square sample sets' methods; every other method's points lie in the
// unit disk (docs/disks.md).
inline constexpr std::string_view kSquareStratified = "square_stratified";
inline constexpr std::string_view kSquareR2 = "square_r2";

// Where a method's points lie: the unit disk or the square [-1, 1]^2.
enum class SampleShape { disk, square };
SampleShape sample_shape(std::string_view method);

// The one value of the `rotation` key: each pixel turns its round disk by
// interleaved gradient noise, or shifts its square set on the square's torus
// (pcf_poisson, pcss, pcss_minmax).
inline constexpr std::string_view kIgnRotation = "ign";

// A Poisson disk exactly as baked into shaders (float32 values).
struct Disk {
  std::string name;                      // family name from the manifest, e.g. "whitepaper16"
  std::string method;                    // "whitepaper" or a generate_disk method (docs/disks.md)
  std::uint64_t seed = 0;                // generator seed (0 for whitepaper16)
  std::vector<Point2> points;            // the baked points, in order
  double normalized_min_distance = 0.0;  // min pairwise distance / hexagonal-packing bound
};

// The keys that select a variant of a technique. Unused keys stay empty.
// Every member has an initializer, so that designated initializers naming
// only some keys ({.kernel = 8}) raise no missing-initializer warning.
struct VariantKeys {
  std::optional<int> kernel = std::nullopt;           // pcf_grid: odd K; minmax_pcf: any K
  std::optional<int> blocker_samples = std::nullopt;  // pcss
  std::optional<int> pcf_samples = std::nullopt;      // pcf_poisson, pcss, pcss_minmax
  std::optional<std::string> disk = std::nullopt;     // disk family: pcf_poisson, pcss, pcss_minmax
  std::optional<std::string> traversal = std::nullopt;  // minmax_pcf, backprojection: "brute_force"
  std::optional<int> max_nodes = std::nullopt;          // (bitmask_)backprojection: work bound
  std::optional<int> blur_radius = std::nullopt;   // screen_blur: taps each side (sigma = R / 2)
  std::optional<bool> depth_aware = std::nullopt;  // screen_blur: true, or unset for false
  std::optional<int> light_bits = std::nullopt;    // bitmask_backprojection: N light samples
  std::optional<std::string> rotation = std::nullopt;  // disk techniques: "ign" per pixel
  std::optional<bool> receiver_plane = std::nullopt;   // pcf_poisson, pcss: true, or unset
  // hard, pcf_grid, pcf_poisson, pcss: "perspective" or "perspective_reversed"
  // (map_encoding.hpp), or unset for linear.
  std::optional<std::string> map_encoding = std::nullopt;
  // hard, pcf_grid, pcf_poisson, pcss: "atlas" (map_layout.hpp), or unset
  // for a map of its own.
  std::optional<std::string> map_layout = std::nullopt;
};

// The keys' names, in the one order every listing of keys follows.
inline constexpr std::array<std::string_view, 13> kVariantKeyNames = {
    "kernel",         "blocker_samples", "pcf_samples", "disk",       "traversal",
    "max_nodes",      "blur_radius",     "depth_aware", "light_bits", "rotation",
    "receiver_plane", "map_encoding",    "map_layout"};

// Calls f(name, key) for each key in kVariantKeyNames order, set or not; `key`
// is the std::optional member, const when `keys` is.
template <typename Keys, typename F>
requires std::same_as<std::remove_const_t<Keys>, VariantKeys>
void for_each_key(Keys& keys, F&& f) {
  f(kVariantKeyNames[0], keys.kernel);
  f(kVariantKeyNames[1], keys.blocker_samples);
  f(kVariantKeyNames[2], keys.pcf_samples);
  f(kVariantKeyNames[3], keys.disk);
  f(kVariantKeyNames[4], keys.traversal);
  f(kVariantKeyNames[5], keys.max_nodes);
  f(kVariantKeyNames[6], keys.blur_radius);
  f(kVariantKeyNames[7], keys.depth_aware);
  f(kVariantKeyNames[8], keys.light_bits);
  f(kVariantKeyNames[9], keys.rotation);
  f(kVariantKeyNames[10], keys.receiver_plane);
  f(kVariantKeyNames[11], keys.map_encoding);
  f(kVariantKeyNames[12], keys.map_layout);
}

// minmax_pcf's baked 1 / K^2 (MINMAX_PCF_INV_AREA), rounded to float. The
// visibility is 1 for C = 0 (K^2 times the rounded 1 / K^2 may be just below
// 1) and float(K^2 - C) times it otherwise: one correctly rounded product of
// exact operands, within one ulp of 1 - C / K^2 and 0 for C = K^2, which no
// compiler can contract or reorder, so it is the same on every target and
// in the reference. A division is not: GLSL allows it 2.5 ulp, and HLSL
// compilers replace a division by a constant with a reciprocal product.
inline float minmax_pcf_inv_area(int kernel) {
  return 1.0f / static_cast<float>(kernel * kernel);
}

// For minmax_pcf with kernel K: the most nodes the depth-first walk of
// shaderlib/common/minmax_traversal.glsl can visit over a K x K window, for
// any map and position (minmax_max_steps() derives its loop bound).
int minmax_max_visits(int kernel);

// MINMAX_MAX_STEPS before a target's cap: the most steps of that walk. A
// step stands on a node or rises from a finished group of four children,
// once per descended node, and every descent adds four visits, so
// visits + (visits - 4) / 4.
int minmax_max_steps(int kernel);

// screen_blur's baked weights (BLUR_WEIGHTS, index.json `blur_weights`) for
// radius R >= 1: w_k = exp(-k^2 / (2 sigma^2)) with sigma = R / 2 for
// k = -R..R, divided by their sum in double and then rounded to float.
std::vector<float> gaussian_weights(int radius);

// One fully specified permutation: what gets compiled and verified.
struct Variant {
  std::string name;  // stable, e.g. "pcss_b16_p16_whitepaper16"
  Technique technique = Technique::hard;
  VariantKeys keys;
  std::optional<Disk> blocker_disk;  // pcss only
  std::optional<Disk> pcf_disk;      // pcf_poisson and pcss
  std::vector<Target> targets;       // targets this variant is emitted for, in kAllTargets order
  std::vector<float> blur_weights;   // screen_blur: baked Gaussian weights, taps -R..R
  // The forms asked for, in kAllForms order; those the technique has are
  // built (builds_form(), penumbra/model/shader_contract.hpp).
  std::vector<Form> forms{kAllForms.begin(), kAllForms.end()};
};

// Builds the stable variant name from technique and keys:
// hard, pcf_grid_k5, pcf_poisson_p16_poisson, pcss_b16_p16_whitepaper16,
// minmax_pcf_k16_brute_force, backprojection_n4096, screen_blur_r4_depth_aware,
// bitmask_backprojection_bits256, pcss_b16_p16_poisson_ign_receiver_plane,
// pcf_grid_k3_perspective_reversed.
std::string variant_name(Technique technique, const VariantKeys& keys);

// A library's order of variants: technique order, then keys ascending (a
// key left out first). Names are unique, so the order is total.
bool variant_less(const Variant& a, const Variant& b);

// The steps `variant`'s walk may take (minmax_pcf: MINMAX_MAX_STEPS,
// backprojection: BACKPROJECTION_MAX_STEPS; with the brute_force traversal
// a step reads one texel): the walk's own bound, capped by `limit` when it
// is positive (a target's walk_step_limit); nullopt for techniques without
// a walk. Below the walk's own bound the result depends on the cap, and
// the reference models it.
std::optional<int> walk_step_bound(const Variant& variant, int limit = 0);

// minmax_pcf promises the exact count C, which a walk that `target`'s
// walk_step_limit stops short cannot give, so such a variant is not built
// for that target: why, or empty when `variant` keeps the promise there
// (every other technique, every target without a cap, and every walk whose
// worst case, walk_step_bound(), fits the cap). The message names the
// variant, the target, the worst case, the cap and the largest kernel that
// fits; callers add what to do in their context.
std::string inexact_walk(const Variant& variant, Target target);

// backprojection and bitmask_backprojection: the techniques whose shaders
// run the back-projection walk (common/backprojection_walk.glsl), bounded by
// `max_nodes`.
bool walks_backprojection(Technique technique);

}  // namespace penumbra
