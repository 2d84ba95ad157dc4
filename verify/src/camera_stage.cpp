#include "camera_stage.hpp"

#include <algorithm>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/verify/shadow_params.hpp"

namespace penumbra {

Result<CameraStage> camera_stage(Engine& engine, const Library& library,
                                 const LibraryVariant& entry, Target target,
                                 DepthFormat map_format) {
  CameraStage out;
  out.stage = reference::report_stage();
  out.stage.scene = reference::for_map_encoding(out.stage.scene, map_encoding(entry.variant.keys));
  out.width = out.stage.scene.receivers_width;
  out.height = out.stage.scene.receivers_height;
  out.view = reference::view(out.stage, out.width, out.height);
  PENUMBRA_TRY_ASSIGN(ExecutableProgram depth,
                      load_executable(library, entry, PassKind::depth, target));
  PENUMBRA_TRY_ASSIGN(out.fixture, prepare_scene(engine, depth.program, target, out.stage.scene,
                                                 out.view.receivers, map_format));
  out.depth = std::move(depth.program.reflection);
  return out;
}

EngineFormCheck started_check(const LibraryVariant& entry, Target target, const Backend& backend) {
  EngineFormCheck check;
  check.variant = entry.variant.name;
  check.target = target;
  check.backend = backend.name();
  return check;
}

Status judge_picture(EngineFormCheck& check, Engine& engine, const LibraryVariant& entry,
                     const CameraStage& camera, const std::shared_ptr<const FloatImage>& own_map,
                     const FloatImage& receivers, const FloatImage& visibility, int channel,
                     std::span<const FloatImage> rounded) {
  const SceneFixture& fixture = camera.fixture;
  // A path's own map (Wine's runtimes draw theirs) is in the fixture's depth
  // format, as the Vulkan one is.
  EngineMap map{own_map ? *own_map : fixture.normalized_depth, fixture.encoded,
                depth_scale_for(fixture.scene.far_z)};
  check.map_format = map.encoded ? map.encoded->format : DepthFormat::d32_float;
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, engine.device_info().sub_texel_precision_bits))};
  PENUMBRA_TRY_ASSIGN(
      const StagePictureCheck picture,
      check_stage_picture(entry.variant, camera.stage, camera.view, map, fixture.scene.light,
                          receivers, visibility, channel, precision,
                          reference::shader_limits(check.target), rounded));
  check.comparison = picture.comparison;
  check.surface_pixels = picture.surface_pixels;
  check.camera_agreement = picture.camera_agreement;
  check.pass = picture.pass;
  return {};
}

}  // namespace penumbra
