#include "penumbra/verify/stage_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace penumbra {
namespace {

// The face of the stage the ray cast's point `p` lies on: 0 for the
// ground, 1 + 6 b + k for face k of box b; -1 for none.
int face_of(const reference::Scene& scene, const std::array<double, 3>& p,
            reference::Surface surface) {
  if (surface == reference::Surface::none) return -1;
  if (surface == reference::Surface::ground) return 0;
  int nearest = -1;
  double distance = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < scene.boxes.size(); ++b) {
    const reference::Box& box = scene.boxes[b];
    const double planes[6] = {box.x0, box.x1, box.y0, box.y1, box.z0, box.z1};
    for (int k = 0; k < 6; ++k) {
      const double d = std::abs(p[std::size_t(k / 2)] - planes[k]);
      if (d < distance) {
        distance = d;
        nearest = 1 + 6 * int(b) + k;
      }
    }
  }
  return nearest;
}

// See StagePictureCheck::camera_agreement.
double camera_agreement(const reference::StageView& view, const FloatImage& gpu) {
  std::size_t surfaces = 0, agreeing = 0;
  for (int j = 0; j < gpu.height; ++j) {
    for (int i = 0; i < gpu.width; ++i) {
      if (view.surfaces[std::size_t(j) * gpu.width + i] == reference::Surface::none) continue;
      ++surfaces;
      const double z = view.receivers.at(i, j, 2);
      agreeing += std::abs(gpu.at(i, j, 0) - view.receivers.at(i, j, 0)) < 1e-3 &&
                  std::abs(gpu.at(i, j, 1) - view.receivers.at(i, j, 1)) < 1e-3 &&
                  std::abs(gpu.at(i, j, 2) - z) < 1e-3 * z;
    }
  }
  return surfaces ? double(agreeing) / double(surfaces) : 0.0;
}

// `map`'s depths as linear z, for an unencoded map.
FloatImage linear_depths(const EngineMap& map) {
  FloatImage linear = map.stored;
  for (float& d : linear.data) d = float(d / map.depth_scale);  // exact: a power of two
  return linear;
}

// The reference at `receivers` on `map`.
Result<reference::ReferenceImage> reference_at(const Variant& variant, const EngineMap& map,
                                               const LightParams& light,
                                               const FloatImage& receivers,
                                               const reference::SamplingPrecision& precision,
                                               const reference::ShaderLimits& limits) {
  if (map.encoded) {
    return reference::evaluate_image(variant, map.stored, *map.encoded, light, receivers, precision,
                                     limits);
  }
  return reference::evaluate_image(variant, linear_depths(map), light, receivers, precision,
                                   limits);
}

// Widens `expected` at `pixels` by the reference at each of `rounded`:
// receiver_rounding where it differs by over half the tolerance, and its
// value in [low, high]. The map is decoded once for all of them, without
// an encoded map's depth-tie evaluations.
Status widen_by_rounding(reference::ReferenceImage& expected, const Variant& variant,
                         const EngineMap& map, const LightParams& light,
                         const RoundedReceivers& rounded, std::span<const std::size_t> pixels,
                         const reference::SamplingPrecision& precision,
                         const reference::ShaderLimits& limits) {
  if (pixels.empty() || !rounded) return {};
  const std::vector<FloatImage> alternatives = rounded();
  const FloatImage linear = map.encoded ? FloatImage() : linear_depths(map);
  const reference::ShadowMapView view = map.encoded
                                            ? reference::ShadowMapView(map.stored, *map.encoded)
                                            : reference::ShadowMapView(linear);
  const double half_tolerance = 0.5 * reference::tolerance(variant.technique, precision);
  PENUMBRA_TRY_ASSIGN(const std::vector<FloatImage> others,
                      reference::evaluate_visibility(variant, view, light, alternatives, pixels,
                                                     precision, limits));
  for (const FloatImage& other : others) {
    for (const std::size_t at : pixels) {
      const float value = other.data[at];
      const double apart = std::abs(double(expected.visibility.data[at]) - value);
      const auto reasons =
          reference::Ambiguity(std::uint16_t(expected.ambiguous.data[at])) |
          reference::ambiguous_if(apart > half_tolerance, reference::Ambiguity::receiver_rounding);
      expected.ambiguous.data[at] = float(std::uint16_t(reasons));
      expected.low.data[at] = std::min(expected.low.data[at], value);
      expected.high.data[at] = std::max(expected.high.data[at], value);
    }
  }
  return {};
}

}  // namespace

Result<reference::ReferenceImage> PictureReferences::get(
    const Variant& variant, const EngineMap& map, const LightParams& light,
    const FloatImage& receivers, const reference::SamplingPrecision& precision,
    const reference::ShaderLimits& limits) {
  for (const Entry& e : entries_) {
    if (e.variant == variant.name && e.light == light &&
        e.sub_texel_bits == precision.sub_texel_bits && e.limits == limits &&
        e.encoded == map.encoded && e.depth_scale == map.depth_scale &&
        same_bytes(e.map, map.stored) && same_bytes(e.receivers, receivers)) {
      return e.value;
    }
  }
  PENUMBRA_TRY_ASSIGN(reference::ReferenceImage value,
                      reference_at(variant, map, light, receivers, precision, limits));
  entries_.push_back({variant.name, light, precision.sub_texel_bits, limits, map.encoded,
                      map.depth_scale, map.stored, receivers, value});
  return value;
}

FloatImage receivers_from_clip(const FloatImage& clip, int w_channel, double v_sign,
                               bool orthographic) {
  FloatImage out(clip.width, clip.height, 3);
  for (int j = 0; j < clip.height; ++j) {
    for (int i = 0; i < clip.width; ++i) {
      const double z_r = clip.at(i, j, w_channel);
      if (!(z_r > 0.0)) {
        out.at(i, j, 0) = out.at(i, j, 1) = 0.5f;
        out.at(i, j, 2) = 0.0f;
        continue;
      }
      const double w = orthographic ? 1.0 : z_r;
      out.at(i, j, 0) = float(0.5 + 0.5 * (clip.at(i, j, 0) / w));
      out.at(i, j, 1) = float(0.5 + v_sign * (clip.at(i, j, 1) / w));
      out.at(i, j, 2) = float(z_r);
    }
  }
  return out;
}

std::vector<std::size_t> face_pixels(const reference::Stage& stage,
                                     const reference::StageView& view,
                                     const FloatImage& receivers) {
  // Each pixel's face, found once: every pixel is read by its quad's four.
  std::vector<int> faces(receivers.pixel_count());
  for (int y = 0; y < receivers.height; ++y) {
    for (int x = 0; x < receivers.width; ++x) {
      const std::size_t k = std::size_t(y) * receivers.width + x;
      faces[k] = receivers.at(x, y, 2) > 0.0f
                     ? face_of(stage.scene, view.points[k], view.surfaces[k])
                     : -1;
    }
  }
  const auto face = [&](int x, int y) { return faces[std::size_t(y) * receivers.width + x]; };
  // A box's side is parallel to a directional light's rays: the map sees it
  // edge-on, so its every point lies on an occluder's silhouette (a tie),
  // and it receives no light at any visibility.
  const auto judged = [&](int k) {
    return k >= 0 && !(stage.scene.light.orthographic() && k > 0 && (k - 1) % 6 < 4);
  };
  std::vector<std::size_t> out;
  for (int j = 0; j < receivers.height; ++j) {
    for (int i = 0; i < receivers.width; ++i) {
      const int own = face(i, j);
      bool inside = judged(own);
      const int qi = i & ~1, qj = j & ~1;
      for (int d = 0; d < 4 && inside; ++d) {
        const int x = std::min(qi + d % 2, receivers.width - 1);
        const int y = std::min(qj + d / 2, receivers.height - 1);
        inside = face(x, y) == own;
      }
      if (inside) out.push_back(std::size_t(j) * receivers.width + i);
    }
  }
  return out;
}

Result<StagePictureCheck> check_stage_picture(
    const Variant& variant, const reference::Stage& stage, const reference::StageView& view,
    const EngineMap& map, const LightParams& light, const FloatImage& receivers,
    const FloatImage& visibility, int channel, const reference::SamplingPrecision& precision,
    const reference::ShaderLimits& limits, const RoundedReceivers& rounded,
    PictureReferences* references) {
  PENUMBRA_TRY_ASSIGN(reference::ReferenceImage expected,
                      references
                          ? references->get(variant, map, light, receivers, precision, limits)
                          : reference_at(variant, map, light, receivers, precision, limits));
  const double tolerance = reference::tolerance(variant.technique, precision);
  StagePictureCheck check;
  check.camera_agreement = camera_agreement(view, receivers);
  const std::vector<std::size_t> inside = face_pixels(stage, view, receivers);
  const auto gpu_at = [&](std::size_t at) {
    return visibility.data[std::size_t(visibility.channels) * at + std::size_t(channel)];
  };
  // `expected.low` and `high`: the reference's range over the maps and
  // receivers a shader may in effect have used; a pixel ambiguous only
  // where the receiver rounds or depths tie is compared with its nearest
  // value, or left out where the GPU misses the range.
  constexpr auto kRanged =
      std::uint16_t(reference::Ambiguity::receiver_rounding | reference::Ambiguity::depth_tie);
  const auto target = [&](std::size_t at) {
    const auto reasons = std::uint16_t(expected.ambiguous.data[at]);
    return reasons == 0 ? expected.visibility.data[at]
                        : std::clamp(gpu_at(at), expected.low.data[at], expected.high.data[at]);
  };
  // The rounded receivers can change the outcome only of a compared pixel
  // where the GPU misses the reference, and the reference is costly (a
  // back-projection's walk): only the pixels further from it than a tenth
  // of the tolerance are evaluated there, which keeps the reported errors
  // those against the range wherever they exceed that.
  const double open_beyond = 0.1 * tolerance;
  std::vector<std::size_t> open;
  for (const std::size_t at : inside) {
    const auto reasons = std::uint16_t(expected.ambiguous.data[at]);
    if ((reasons & ~kRanged) == 0 && std::abs(double(gpu_at(at)) - target(at)) > open_beyond) {
      open.push_back(at);
    }
  }
  PENUMBRA_TRY(widen_by_rounding(expected, variant, map, light, rounded, open, precision, limits));
  const int count = int(inside.size());
  FloatImage gpu(count, 1, 1), reference(count, 1, 1), ambiguous(count, 1, 1);
  for (std::size_t k = 0; k < inside.size(); ++k) {
    const std::size_t at = inside[k];
    const auto reasons = std::uint16_t(expected.ambiguous.data[at]);
    gpu.data[k] = gpu_at(at);
    reference.data[k] = expected.visibility.data[at];
    ambiguous.data[k] = expected.ambiguous.data[at];
    if (reasons != 0 && (reasons & ~kRanged) == 0 &&
        std::abs(double(gpu.data[k]) - target(at)) <= tolerance) {
      reference.data[k] = target(at);
      ambiguous.data[k] = 0.0f;
    }
  }
  check.surface_pixels = inside.size();

  PENUMBRA_TRY_ASSIGN(check.comparison, reference::compare(gpu, reference, ambiguous, tolerance));
  check.pass = check.comparison.pass && check.camera_agreement >= kMinCameraAgreement;
  return check;
}

}  // namespace penumbra
