// The techniques of docs/techniques.md, each a direct reading of its row:
// the first four here, the min-max mip ones and screen_blur's factor in
// their own files (technique_parts.hpp); technique_table.cpp says which
// serves which technique. Every comparison uses z_r - bias;
// geometry (search width, penumbra, filter radius) uses the unbiased z_r, as
// in the NVIDIA PCSS whitepaper.
#include "penumbra/reference/techniques.hpp"

#include <algorithm>
#include <optional>

#include "penumbra/model/target_traits.hpp"
#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"
#include "technique_table.hpp"

namespace penumbra::reference {
namespace detail {

Sample point_compare(const ShadowMapView& map, double u, double v, double z_ref,
                     const SamplingPrecision& precision) {
  const TexelCandidates texels = candidate_texels(map, u, v, precision.point_window());
  auto lit_at = [&](Texel t) { return lit(z_ref, map.depth(t.i, t.j)); };
  return {lit_at(texels.texels[0]) ? 1.0 : 0.0,
          ambiguous_if(varies(texels, lit_at), Ambiguity::texel_boundary)};
}

double pcf_grid(const ShadowMapView& map, const Query& q, double z_ref, int kernel) {
  const int half = (kernel - 1) / 2;
  double sum = 0.0;
  for (int j = -half; j <= half; ++j) {
    for (int i = -half; i <= half; ++i) {
      sum += bilinear_compare(map, q.u + double(i) / map.width(), q.v + double(j) / map.height(),
                              z_ref);
    }
  }
  return sum / (double(kernel) * kernel);
}

double pcss_filter_radius(const LightParams& light, double z_receiver, double z_blocker) {
  if (light.orthographic()) return light.light_size_uv() * (z_receiver - z_blocker);
  const double penumbra = (z_receiver - z_blocker) / z_blocker;
  return penumbra * light.light_size_uv() * light.near_plane / z_receiver;
}

Sample pcss(const ShadowMapView& map, const LightParams& light, const Query& q, double z_ref,
            const Disk& blocker_disk, const Disk& pcf_disk, const SamplingPrecision& precision) {
  // Up to the near plane the search width is 0 or negative: a rendered map
  // holds nothing there to occlude the receiver.
  if (!(q.z > light.near_plane)) return {1.0};
  // Step 1, blocker search: point samples over the light's footprint on the
  // near plane, seen from the receiver.
  const double search_width = pcss_search_width(light, q.z);
  // What one blocker sample contributes against reference `z`: its depth
  // when it occludes.
  auto blocker_against = [&](double z) {
    return [&map, z](Texel t) -> std::optional<double> {
      const double depth = map.depth(t.i, t.j);
      if (lit(z, depth)) return std::nullopt;
      return depth;
    };
  };
  double blocker_sum = 0.0;
  int blockers = 0;
  Ambiguity ambiguous = Ambiguity::none;
  for (const Point2& d : blocker_disk.points) {
    const double du = d[0] * search_width;
    const double dv = d[1] * search_width;
    // Along the receiver's plane where the variant has receiver_plane.
    const auto blocker_at = blocker_against(z_ref + q.dz_du * du + q.dz_dv * dv);
    const TexelCandidates texels =
        candidate_texels(map, q.u + du, q.v + dv, precision.point_window());
    ambiguous |= ambiguous_if(varies(texels, blocker_at), Ambiguity::texel_boundary);
    if (const auto depth = blocker_at(texels.texels[0])) {
      blocker_sum += *depth;
      ++blockers;
    }
  }
  if (blockers == 0) return {1.0, ambiguous};

  // Step 2, penumbra size by the parallel-plane estimate, the blocker no
  // nearer than the near plane as in pcss_minmax (a rendered map holds
  // nothing nearer; a blocker at z = 0 would make the penumbra infinite).
  const double avg_blocker_depth = std::max(blocker_sum / blockers, light.near_plane);
  const double filter_radius_uv = pcss_filter_radius(light, q.z, avg_blocker_depth);

  // Step 3, filtering.
  return {poisson_pcf(map, q, z_ref, pcf_disk.points, filter_radius_uv), ambiguous};
}

}  // namespace detail

namespace {

// `mip` may be null for the techniques whose reference does not read it.
Sample dispatch(const Variant& variant, const ShadowMapView& map, const MinMaxMip* mip,
                const LightParams& light, const Query& query, const SamplingPrecision& precision,
                const ShaderLimits& limits) {
  // At or behind the light nothing can occlude the receiver, and the
  // techniques' geometry divides by z_r; `!(>)` also takes NaN.
  if (!(query.z > 0.0)) return {1.0};
  Query q = query;
  q.z = std::min(q.z, kMaxReceiverDepth);
  return detail::reference_for(variant.technique)
      .evaluate({variant, map, mip, light, q, q.z - light.bias, precision, limits});
}

}  // namespace

ShaderLimits shader_limits(Target target) {
  return {traits(target).walk_step_limit};
}

FloatImage screen_visibility(const Variant& variant, FloatImage visibility,
                             const FloatImage& receivers) {
  const auto filter = detail::reference_for(variant.technique).screen_filter;
  return filter ? filter(variant, visibility, receivers) : visibility;
}

bool filters_screen(Technique technique) {
  return detail::reference_for(technique).screen_filter != nullptr;
}

bool reference_reads_mip(Technique technique) {
  return detail::reference_for(technique).reads_mip;
}

Sample evaluate(const Variant& variant, const ShadowMapView& map, const MinMaxMip& mip,
                const LightParams& light, const Query& query, const SamplingPrecision& precision,
                const ShaderLimits& limits) {
  return dispatch(variant, map, &mip, light, query, precision, limits);
}

Sample evaluate(const Variant& variant, const ShadowMapView& map, const LightParams& light,
                const Query& query, const SamplingPrecision& precision,
                const ShaderLimits& limits) {
  if (!reference_reads_mip(variant.technique))
    return dispatch(variant, map, nullptr, light, query, precision, limits);
  const MinMaxMip mip(map);
  return dispatch(variant, map, &mip, light, query, precision, limits);
}

}  // namespace penumbra::reference
