#include "technique_table.hpp"

#include <cstddef>
#include <optional>

#include "penumbra/reference/screen_blur.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// Float32 arithmetic and storage of a visibility in [0, 1] stay well below this.
constexpr double kFloatSlack = 1e-5;

// Point samples give exactly 0 or 1; the GPU can only differ by reading
// another texel, and those pixels are marked ambiguous and skipped.
double point_tolerance(const SamplingPrecision&) {
  return kFloatSlack;
}

// A bilinear comparison is w . c with c in {0, 1}^4. If each axis weight is
// off by at most one step e, the blend moves by at most |da| + |db| <= 2e,
// and a mean of such samples by no more.
double bilinear_tolerance(const SamplingPrecision& precision) {
  return 2 * precision.reach() + kFloatSlack;
}

// The steps of the variant's walk where the target's cap stops it short of
// its own bound; nullopt when the walk runs its course.
std::optional<int> capped_walk_steps(const ReceiverInputs& in) {
  const std::optional<int> own = walk_step_bound(in.variant);
  const std::optional<int> capped = walk_step_bound(in.variant, in.limits.walk_steps);
  if (own && capped && *capped < *own) return capped;
  return std::nullopt;
}

Status needs_nothing(const Variant&) {
  return {};
}

Status needs_pcf_disk(const Variant& v) {
  PENUMBRA_TRY(check_rotation(v));
  return check_disk(v, v.pcf_disk, "pcf", v.keys.pcf_samples, "pcf_samples");
}

// The back-projections' result, `walk()`, for an area light. A point light
// (L = 0) has no area to cover: its shadow is the hard test of the texel the
// receiver's ray to the light crosses.
template <typename Walk>
Sample unless_point_light(const ReceiverInputs& in, Walk walk) {
  if (!(in.light.light_world_size > 0.0)) {
    return point_compare(in.map, in.query.u, in.query.v, in.z_ref, in.precision);
  }
  return walk();
}

// A sample also marked where placed_disk() put a point on its seam.
Sample with_seam(Sample sample, bool seam) {
  sample.ambiguous |= ambiguous_if(seam, Ambiguity::rotation_seam);
  return sample;
}

// Indexed by Technique.
constexpr TechniqueReference kReferences[] = {
    {Technique::hard, false, needs_nothing,
     [](const ReceiverInputs& in) {
       return point_compare(in.map, in.query.u, in.query.v, in.z_ref, in.precision);
     },
     point_tolerance},
    {Technique::pcf_grid, false,
     [](const Variant& v) { return check_kernel(v, kMaxSamples, true); },
     [](const ReceiverInputs& in) {
       return Sample{pcf_grid(in.map, in.query, in.z_ref, in.variant.keys.kernel.value())};
     },
     bilinear_tolerance},
    {Technique::pcf_poisson, false, needs_pcf_disk,
     [](const ReceiverInputs& in) {
       bool seam = false;
       const Disk pcf = placed_disk(in.variant.pcf_disk.value(), in.variant.keys, in.query, seam);
       return with_seam(Sample{poisson_pcf(in.map, in.query, in.z_ref, pcf.points,
                                           in.light.filter_radius(in.map.width()))},
                        seam);
     },
     bilinear_tolerance},
    {Technique::pcss, false,
     [](const Variant& v) -> Status {
       PENUMBRA_TRY(
           check_disk(v, v.blocker_disk, "blocker", v.keys.blocker_samples, "blocker_samples"));
       return needs_pcf_disk(v);
     },
     [](const ReceiverInputs& in) {
       bool seam = false;
       const VariantKeys& keys = in.variant.keys;
       const Disk blocker = placed_disk(in.variant.blocker_disk.value(), keys, in.query, seam);
       const Disk pcf = placed_disk(in.variant.pcf_disk.value(), keys, in.query, seam);
       return with_seam(pcss(in.map, in.light, in.query, in.z_ref, blocker, pcf, in.precision),
                        seam);
     },
     bilinear_tolerance},
    // Its reference counts texel by texel, or walks the mip where a cap stops the walk.
    {Technique::minmax_pcf, true,
     [](const Variant& v) -> Status {
       PENUMBRA_TRY(check_kernel(v, kMaxSamples, false));
       return check_traversal(v);
     },
     [](const ReceiverInputs& in) {
       return minmax_pcf(in.map, *in.mip, in.light, in.query, in.variant.keys,
                         capped_walk_steps(in));
     },
     // An integer count of point compares, 1 - C / K^2 in float: bit-exact.
     [](const SamplingPrecision&) { return 0.0; }},
    {Technique::backprojection, true,
     [](const Variant& v) -> Status {
       PENUMBRA_TRY(check_max_nodes(v));
       return check_traversal(v);
     },
     [](const ReceiverInputs& in) {
       return unless_point_light(in, [&] {
         return backprojection(in.map, *in.mip, in.light, in.query, in.variant.keys,
                               capped_walk_steps(in));
       });
     },
     // Exact compares; only float32 sums of patch areas differ.
     [](const SamplingPrecision&) { return kBackprojectionTolerance; }},
    {Technique::pcss_minmax, true, needs_pcf_disk,
     [](const ReceiverInputs& in) {
       bool seam = false;
       const Disk pcf = placed_disk(in.variant.pcf_disk.value(), in.variant.keys, in.query, seam);
       return with_seam(pcss_minmax(in.map, *in.mip, in.light, in.query, pcf, in.precision), seam);
     },
     bilinear_tolerance},
    // The factor: a mean of 9 point samples, n / 9 for an integer n, as exact
    // as hard's once an ambiguous sample marks the pixel. (The blur and
    // composite are checked against the CPU chain run on the GPU's own
    // images: docs/verification.md, "screen_blur".)
    {Technique::screen_blur, false, check_blur,
     [](const ReceiverInputs& in) {
       return screen_blur_factor(in.map, in.query, in.z_ref, in.precision);
     },
     point_tolerance, screen_blur},
    {Technique::bitmask_backprojection, true,
     [](const Variant& v) -> Status {
       PENUMBRA_TRY(check_light_bits(v));
       PENUMBRA_TRY(check_max_nodes(v));
       return check_traversal(v);
     },
     [](const ReceiverInputs& in) {
       return unless_point_light(in, [&] {
         return bitmask_backprojection(in.map, *in.mip, in.light, in.query, in.variant.keys,
                                       *walk_step_bound(in.variant, in.limits.walk_steps));
       });
     },
     // Whole bits over a power-of-two N: exact, undecided bits aside.
     [](const SamplingPrecision&) { return 0.0; }},
};

constexpr bool rows_in_enum_order() {
  for (std::size_t i = 0; i < std::size(kReferences); ++i) {
    if (static_cast<std::size_t>(kReferences[i].technique) != i) return false;
  }
  return std::size(kReferences) == kAllTechniques.size();
}
static_assert(rows_in_enum_order());

}  // namespace

const TechniqueReference& reference_for(Technique technique) {
  return kReferences[static_cast<std::size_t>(technique)];
}

}  // namespace penumbra::reference::detail
