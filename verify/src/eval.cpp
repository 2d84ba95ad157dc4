#include "penumbra/verify/eval.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "eval_placement.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "scene_passes.hpp"

namespace penumbra {
namespace {

// The far end of the normalized range: the largest finite map depth and
// comparison reference z_r - bias, receivers held at kMaxReceiverDepth as
// the shaders hold them. Every reference is then <= 1, so a texel stored as
// 1 (normalized_map()) occludes nothing.
double max_depth(const EvalInputs& inputs) {
  constexpr double kFar = reference::kMaxReceiverDepth;
  double max_z = 0.0;
  for (float z : inputs.shadow_map.data) {
    if (std::isfinite(z)) max_z = std::max(max_z, std::min(double(z), kFar));
  }
  const double behind = std::max(0.0, -inputs.light.bias);
  for (std::size_t p = 0; p < inputs.receivers.pixel_count(); ++p) {
    const double z = inputs.receivers.data[p * 3 + 2];
    if (z > 0.0) max_z = std::max(max_z, std::min(z, kFar) + behind);  // not NaN
  }
  return max_z;
}

// The map as the device stores it, z * depth_scale (exact: a power of two),
// in the [0, 1] a depth image holds: NaN, infinite and farther texels are
// stored as 1, like the reference's +inf they occlude no receiver.
FloatImage normalized_map(const FloatImage& map, float depth_scale) {
  FloatImage normalized = map;
  for (float& d : normalized.data) d = d * depth_scale <= 1.0f ? d * depth_scale : 1.0f;
  return normalized;
}

// The encoding of `variant`'s map and its projection: the light's near
// plane, and 1 / depth_scale for the far one. None for eval's own linear map;
// a stored map is decoded texel by texel, a linear one too.
std::optional<reference::EncodedDepth> encoding_of(const LibraryVariant& variant,
                                                   const EvalInputs& inputs, float depth_scale) {
  const MapEncoding encoding = map_encoding(variant.variant.keys);
  if (!inputs.stored_far) return reference::encoded_depth(encoding, inputs.light, depth_scale);
  return reference::EncodedDepth{encoding, {inputs.light.near_plane, 1.0 / depth_scale}};
}

// The depth scale the shaders get: 1 / the engine's far plane for a stored
// map, else a power of two that keeps every depth of eval's own in [0, 1].
float depth_scale_of(const EvalInputs& inputs) {
  return inputs.stored_far ? float(1.0 / *inputs.stored_far) : depth_scale_for(max_depth(inputs));
}

// The map as the variant's programs read it: a stored map as given; a
// linear one normalized, or stored in its encoding, nearer than the near
// plane as the near plane and farther than the far one as the far one, as
// a depth buffer clamps them.
FloatImage stored_map(const EvalInputs& inputs,
                      const std::optional<reference::EncodedDepth>& encoded, float depth_scale) {
  if (inputs.stored_far) return inputs.shadow_map;
  if (!encoded) return normalized_map(inputs.shadow_map, depth_scale);
  FloatImage stored = inputs.shadow_map;
  for (float& d : stored.data) {
    const double z = std::clamp(double(d), encoded->range.near_plane, encoded->range.far_plane);
    d = float(encode_depth(encoded->encoding, std::isnan(d) ? encoded->range.far_plane : z,
                           encoded->range));
  }
  return stored;
}

// The receivers with a NaN depth where the mask says there is none.
FloatImage masked_receivers(const EvalInputs& inputs) {
  FloatImage receivers = inputs.receivers;
  for (std::size_t p = 0; p < inputs.no_receiver.pixel_count(); ++p) {
    if (inputs.no_receiver.data[p] != 0.0f) {
      receivers.data[p * 3 + 2] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  return receivers;
}

// Marks the mask's pixels Ambiguity::no_receiver in `image`'s mask.
void mark_no_receiver(const EvalInputs& inputs, reference::ReferenceImage& image) {
  for (std::size_t p = 0; p < inputs.no_receiver.pixel_count(); ++p) {
    if (inputs.no_receiver.data[p] == 0.0f) continue;
    const auto reasons = reference::Ambiguity(std::uint16_t(image.ambiguous.data[p])) |
                         reference::Ambiguity::no_receiver;
    image.ambiguous.data[p] = float(std::uint16_t(reasons));
  }
}

// One light option's range; `name` is its argument.
Status check_range(const char* name, double value, double low, double high) {
  if (value >= low && value <= high) return {};  // false for NaN
  char range[64];
  std::snprintf(range, sizeof range, "%g to %g", low, high);
  char shown[32];
  std::snprintf(shown, sizeof shown, "%g", value);
  return make_error(Error::Kind::bad_input, std::string(name) + " " + shown,
                    std::string("out of range; allowed: a number from ") + range);
}

// A stored map's texels: depth-buffer values, 0 to 1 (no NaN).
Status check_stored_map(const FloatImage& map) {
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      const float d = map.at(i, j);
      if (d >= 0.0f && d <= 1.0f) continue;  // false for NaN
      char shown[32];
      std::snprintf(shown, sizeof shown, "%g", double(d));
      return make_error(Error::Kind::bad_input, "--shadow-map",
                        "texel (" + std::to_string(i) + ", " + std::to_string(j) + ") holds " +
                            shown +
                            "; a stored map (--map-stored) holds depth-buffer values "
                            "from 0 to 1");
    }
  }
  return {};
}

Status check_images(const EvalInputs& inputs) {
  if (inputs.shadow_map.channels != 1 || inputs.shadow_map.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "--shadow-map",
                      inputs.stored_far
                          ? "expected a one-channel (Pf) image of stored depth"
                          : "expected a one-channel (Pf) image of linear light-view z");
  }
  const FloatImage& receivers = inputs.receivers;
  if (receivers.channels != 3 || receivers.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "--receivers",
                      "expected a three-channel (PF) image of (u, v, z_r)");
  }
  const FloatImage& mask = inputs.no_receiver;
  if (!mask.data.empty() &&
      (mask.channels != 1 || mask.width != receivers.width || mask.height != receivers.height)) {
    return make_error(Error::Kind::bad_input, "--no-receiver",
                      "expected a one-channel (Pf) image of the receivers' size, " +
                          std::to_string(receivers.width) + "x" + std::to_string(receivers.height) +
                          "; got " + std::to_string(mask.width) + "x" +
                          std::to_string(mask.height) + " with " + std::to_string(mask.channels) +
                          " channel(s)");
  }
  PENUMBRA_TRY(check_placement(inputs));
  if (inputs.stored_far) return check_stored_map(inputs.shadow_map);
  if (std::any_of(inputs.shadow_map.data.begin(), inputs.shadow_map.data.end(),
                  [](float z) { return z < 0.0f; })) {
    return make_error(Error::Kind::bad_input, "--shadow-map",
                      "holds a negative depth; linear light-view z is >= 0");
  }
  return {};
}

}  // namespace

Status check_eval_inputs(const EvalInputs& inputs) {
  PENUMBRA_TRY(check_images(inputs));
  const LightParams& light = inputs.light;
  PENUMBRA_TRY(check_range("--light-size", light.light_world_size, 0.0, kMaxLightLength));
  PENUMBRA_TRY(
      check_range("--frustum-width", light.frustum_width, kMinLightLength, kMaxLightLength));
  PENUMBRA_TRY(check_range("--near", light.near_plane, kMinLightLength, kMaxLightLength));
  PENUMBRA_TRY(check_range("--bias", light.bias, -kMaxLightLength, kMaxLightLength));
  if (light.filter_radius_uv) {
    PENUMBRA_TRY(
        check_range("--filter-radius", *light.filter_radius_uv, kMinLightLength, kMaxLightLength));
  }
  if (inputs.stored_far) {
    PENUMBRA_TRY(check_range("--far", *inputs.stored_far, kMinLightLength, kMaxLightLength));
    if (!(*inputs.stored_far > light.near_plane)) {
      char shown[64];
      std::snprintf(shown, sizeof shown, "--far %g", *inputs.stored_far);
      return make_error(Error::Kind::bad_input, shown,
                        "is not beyond the near plane (--near); allowed: a far plane > near");
    }
  }
  return {};
}

Result<QueryOutput> eval_on_device(const Library& library, const LibraryVariant& variant,
                                   Target target, const EvalInputs& inputs, Engine& engine) {
  PENUMBRA_TRY(check_eval_inputs(inputs));
  PENUMBRA_TRY(check_placement_variant(variant, inputs));
  const float depth_scale = depth_scale_of(inputs);
  auto map = engine.upload_shadow_map(device_map(
      stored_map(inputs, encoding_of(variant, inputs, depth_scale), depth_scale), variant, inputs));
  if (!map) return map.error();
  const FloatImage receivers = masked_receivers(inputs);
  const ParamBlock params = device_params(inputs, receivers, depth_scale);
  // The receivers image is the screen; a composite is drawn over
  // reference::scene_colour but not returned.
  const std::vector<PassKind> passes = scene_passes(variant, /*builds_mip=*/false);
  PENUMBRA_TRY_ASSIGN(const LoadedPrograms loaded, load_passes(passes, [&](PassKind pass) {
                        return load_executable(library, variant, pass, target);
                      }));
  if (uses_minmax_mip(variant.variant.technique)) {
    PENUMBRA_TRY(build_library_minmax(engine, library, variant, target, **map, params));
  }
  const FloatImage colour = reference::scene_colour(receivers.width, receivers.height);
  PENUMBRA_TRY_ASSIGN(
      runtime::PassOutputs outputs,
      engine.run_passes(passes, program_map(loaded), **map,
                        {.receivers = &receivers, .scene_colour = &colour}, params));
  return final_visibility(outputs);
}

Result<reference::ReferenceImage> eval_reference(const LibraryVariant& variant, Target target,
                                                 const EvalInputs& inputs) {
  PENUMBRA_TRY(check_eval_inputs(inputs));
  PENUMBRA_TRY(check_placement_variant(variant, inputs));
  const float depth_scale = depth_scale_of(inputs);
  const auto encoded = encoding_of(variant, inputs, depth_scale);
  // An orthographic map's light is directional: --light-size is its half-slope.
  LightParams light = inputs.light;
  if (encoded && is_orthographic(encoded->encoding)) {
    light.projection = LightProjection::orthographic;
  }
  const FloatImage receivers = masked_receivers(inputs);
  // The limits verify_library holds `target`'s runs to: hlsl_dx9's step cap.
  const reference::ShaderLimits limits = reference::shader_limits(target);
  const reference::SamplingPrecision precision = placement_precision(inputs);
  auto image =
      encoded ? reference::evaluate_image(
                    variant.variant, light_map(stored_map(inputs, encoded, depth_scale), inputs),
                    *encoded, light, receivers, precision, limits)
              : reference::evaluate_image(variant.variant, light_map(inputs.shadow_map, inputs),
                                          light, receivers, precision, limits);
  if (!image) return image.error();
  image->visibility =
      reference::screen_visibility(variant.variant, std::move(image->visibility), receivers);
  mark_no_receiver(inputs, *image);
  return image;
}

}  // namespace penumbra
