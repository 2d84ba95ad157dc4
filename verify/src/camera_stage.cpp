#include "camera_stage.hpp"

#include <algorithm>
#include <cmath>

#include "map_placement.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/cascades.hpp"
#include "penumbra/reference/precision.hpp"
#include "scene_truths.hpp"

namespace penumbra {

Result<CameraStage> camera_stage(Engine& engine, SceneTruths& truths, const Library& library,
                                 const LibraryVariant& entry, Target target, DepthFormat map_format,
                                 std::optional<int> cascade) {
  CameraStage out;
  const MapLayout layout = map_layout(entry.variant.keys);
  MapPlacement placement = scene_placement(layout);
  if (cascade) {
    const reference::CascadedStage cascaded = reference::cascaded_stage();
    out.stage = reference::cascade_stage(cascaded, std::size_t(*cascade));
    placement.slot = *cascade;
    placement.slots = int(cascaded.cascades.size());
  } else {
    out.stage = reference::report_stage();
    out.stage.scene =
        reference::for_map_encoding(out.stage.scene, map_encoding(entry.variant.keys));
  }
  out.width = out.stage.scene.receivers_width;
  out.height = out.stage.scene.receivers_height;
  out.view = truths.view(out.stage, out.width, out.height);
  PENUMBRA_TRY_ASSIGN(ExecutableProgram depth,
                      load_executable(library, entry, PassKind::depth, target));
  PENUMBRA_TRY_ASSIGN(out.fixture, prepare_scene(engine, truths, depth.program, target,
                                                 out.stage.scene, out.view.receivers, map_format));
  if (layout != MapLayout::single) {
    PENUMBRA_TRY_ASSIGN(out.fixture, placed_fixture(engine, out.fixture, placement));
  }
  out.depth = std::move(depth.program.reflection);
  return out;
}

std::vector<std::optional<int>> engine_form_stages(const Variant& variant) {
  std::vector<std::optional<int>> out{std::nullopt};
  if (map_encoding(variant.keys) != MapEncoding::orthographic ||
      map_layout(variant.keys) == MapLayout::single) {
    return out;
  }
  static const std::size_t cascades = reference::cascaded_stage().cascades.size();
  for (std::size_t c = 0; c < cascades; ++c) out.emplace_back(int(c));
  return out;
}

Result<const CameraStage*> CameraStages::get(const Library& library, const LibraryVariant& entry,
                                             Target target, std::optional<int> cascade) {
  std::string key;  // stays empty without a depth pass: camera_stage() then errs
  if (const auto depth = entry.passes.find(PassKind::depth); depth != entry.passes.end()) {
    if (const auto files = depth->second.find(target); files != depth->second.end()) {
      key = std::string(to_string(target)) + " " +
            std::string(to_string(map_encoding(entry.variant.keys))) + " " +
            std::string(to_string(map_layout(entry.variant.keys))) + " " + files->second.vert +
            " " + files->second.frag + (cascade ? " cascade " + std::to_string(*cascade) : "");
    }
  }
  if (const auto known = stages_.find(key); known != stages_.end()) return &known->second;
  PENUMBRA_TRY_ASSIGN(CameraStage stage,
                      camera_stage(engine_, truths_, library, entry, target, map_format_, cascade));
  return &stages_.emplace(key, std::move(stage)).first->second;
}

EngineFormCheck started_check(const LibraryVariant& entry, Target target, const Backend& backend,
                              std::optional<int> cascade) {
  EngineFormCheck check;
  check.cascade = cascade;
  check.variant = entry.variant.name;
  check.target = target;
  check.backend = backend.name();
  return check;
}

std::vector<FloatImage> receiver_bounds(const Variant& variant, const FloatImage& exact,
                                        std::span<const FloatImage> rounded,
                                        std::span<const FloatImage> nudged,
                                        const FloatImage& error_bound) {
  constexpr float kRoundingReach = 4.0f;
  FloatImage reach(exact.width, exact.height, exact.channels);
  for (std::size_t k = 0; k < exact.data.size(); ++k) {
    reach.data[k] = std::abs(exact.data[k]) * 0x1p-23f;
    for (std::span<const FloatImage> images : {rounded, nudged}) {
      for (const FloatImage& r : images) {
        reach.data[k] = std::max(reach.data[k], std::abs(r.data[k] - exact.data[k]));
      }
    }
    reach.data[k] = std::max(reach.data[k] * kRoundingReach, error_bound.data[k]);
  }
  // receiver_plane: bit q of `signs` is the sign of quad position
  // q = (i % 2) + 2 (j % 2), and all alike (0 and 15) move no derivative;
  // otherwise bit c is the sign of channel c.
  const bool plane = variant.keys.receiver_plane.value_or(false);
  std::vector<FloatImage> out;
  if (plane) {
    for (int signs = 1; signs <= 14; ++signs) {
      FloatImage& bound = out.emplace_back(exact);
      for (int j = 0; j < exact.height; ++j) {
        for (int i = 0; i < exact.width; ++i) {
          const int bit = (i % 2) + 2 * (j % 2);
          for (int c = 0; c < exact.channels; ++c) {
            bound.at(i, j, c) += (signs >> bit) & 1 ? reach.at(i, j, c) : -reach.at(i, j, c);
          }
        }
      }
    }
    return out;
  }
  // Each channel at -1, 0 or +1 times its reach: the corners, and for an
  // exact count the points between them too (a sample may enter on one
  // side and another leave on the other, so that the corners agree while
  // the count inside the box differs).
  const bool exact_count = reference::tolerance(variant.technique, {}) == 0.0;
  int moves = 1;
  for (int c = 0; c < exact.channels; ++c) moves *= 3;
  for (int move = 0; move < moves; ++move) {
    int step[3] = {};
    bool corner = true, centre = true;
    for (int c = 0, rest = move; c < exact.channels; ++c, rest /= 3) {
      step[c] = rest % 3 - 1;
      corner = corner && step[c] != 0;
      centre = centre && step[c] == 0;
    }
    if (centre || (!corner && !exact_count)) continue;
    FloatImage& bound = out.emplace_back(exact);
    const auto channels = std::size_t(exact.channels);
    for (std::size_t k = 0; k < bound.data.size(); k += channels) {
      for (std::size_t c = 0; c < channels; ++c) {
        bound.data[k + c] += float(step[c]) * reach.data[k + c];
      }
    }
  }
  return out;
}

Status judge_picture(EngineFormCheck& check, Engine& engine, const LibraryVariant& entry,
                     const CameraStage& camera, const std::shared_ptr<const FloatImage>& own_map,
                     const FloatImage& receivers, const FloatImage& visibility, int channel,
                     const RoundedReceivers& rounded, PictureReferences* references) {
  const SceneFixture& fixture = camera.fixture;
  // A path's own map (Wine's runtimes draw theirs) is in the fixture's depth
  // format, as the Vulkan one is.
  EngineMap map{own_map ? *own_map : fixture.normalized_depth, fixture.encoded,
                depth_scale_for(fixture.scene.far_z)};
  check.map_format = map.encoded ? map.encoded->format : DepthFormat::d32_float;
  const reference::SamplingPrecision precision = placement_precision(
      fixture, {static_cast<int>(std::max(1u, engine.device_info().sub_texel_precision_bits))});
  PENUMBRA_TRY_ASSIGN(
      const StagePictureCheck picture,
      check_stage_picture(entry.variant, camera.stage, camera.view, map, fixture.scene.light,
                          receivers, visibility, channel, precision,
                          reference::shader_limits(check.target), rounded, references));
  check.comparison = picture.comparison;
  check.surface_pixels = picture.surface_pixels;
  check.camera_agreement = picture.camera_agreement;
  check.pass = picture.pass;
  return {};
}

}  // namespace penumbra
