#include "penumbra/verify/function_form.hpp"

#include <algorithm>

#include "backend.hpp"
#include "engine_shaders.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/verify/shadow_params.hpp"
#include "scene_fixture.hpp"

namespace penumbra {
namespace {

// The stage's boxes and its ground tile, which the shadow map leaves out
// (a receiver only), as a triangle list in light-view space.
std::vector<std::array<float, 3>> stage_triangles(const reference::Stage& stage) {
  std::vector<std::array<float, 3>> out = reference::triangles(stage.scene);
  const auto h = float(stage.ground_half_width);
  const auto z = float(stage.scene.plane_z0);
  const std::array<float, 3> corners[] = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(corners[k]);
  return out;
}

}  // namespace

Result<FunctionFormCheck> check_function_form(Engine& engine, Backend& backend,
                                              const Library& library, const LibraryVariant& entry,
                                              Target target) {
  const auto form = entry.function.find(target);
  if (form == entry.function.end()) {
    return make_error(
        Error::Kind::bad_input, entry.variant.name,
        "the library has no function form for target " + std::string(to_string(target)));
  }
  const reference::Stage stage = reference::report_stage();
  const reference::Scene& scene = stage.scene;
  const int width = scene.receivers_width, height = scene.receivers_height;
  const reference::StageView view = reference::view(stage, width, height);

  PENUMBRA_TRY_ASSIGN(ExecutableProgram depth,
                      load_executable(library, entry, PassKind::depth, target));
  PENUMBRA_TRY_ASSIGN(SceneFixture fixture,
                      prepare_scene(engine, depth.program, target, scene, view.receivers));

  FunctionFormCheck check;
  check.variant = entry.variant.name;
  check.target = target;
  check.backend = backend.name();
  PENUMBRA_TRY_ASSIGN(const std::string text, read_file(library.root / form->second.file));
  SurfaceDraw draw;
  draw.library = &library;
  draw.entry = &entry;
  draw.target = target;
  draw.where = form->second.file;
  draw.camera = camera_clip(stage, width, height, target);
  draw.light = light_clip(scene.light, target);
  draw.vertex = {takes_pixel(form->second.reflection), width, height};
  draw.function_text = text;
  // The engine's own vertex input, render target and depth buffer: the
  // depth pass's position and depth format, and four floats.
  draw.reflection = form->second.reflection;
  draw.reflection.vertex_inputs = depth.program.reflection.vertex_inputs;
  draw.reflection.depth_target = depth.program.reflection.depth_target;
  draw.reflection.render_targets = {
      {"colour", 0, std::string(api_format(target, TextureFormat::rgba32_float))}};
  draw.triangles = stage_triangles(stage);
  draw.width = width;
  draw.height = height;
  // (x, y, visibility, w) per pixel; the background keeps the clear, 1.
  PENUMBRA_TRY_ASSIGN(const SurfacePicture drawn,
                      backend.draw_surface(draw, fixture, check.execution));
  const FloatImage& clip = drawn.clip;

  fixture.receivers = receivers_from_clip(clip, 3, traits(target).is_hlsl ? -0.5 : 0.5);
  const EngineMap map{drawn.own_stored_depth ? *drawn.own_stored_depth : fixture.normalized_depth,
                      fixture.encoded, depth_scale_for(scene.far_z)};
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, engine.device_info().sub_texel_precision_bits))};
  PENUMBRA_TRY_ASSIGN(
      const StagePictureCheck picture,
      check_stage_picture(entry.variant, stage, view, map, scene.light, fixture.receivers, clip, 2,
                          precision, reference::shader_limits(target)));
  check.comparison = picture.comparison;
  check.surface_pixels = picture.surface_pixels;
  check.camera_agreement = picture.camera_agreement;
  check.pass = picture.pass;
  return check;
}

Result<FunctionFormCheck> check_function_form(Engine& engine, const Library& library,
                                              const LibraryVariant& entry, Target target) {
  const std::unique_ptr<Backend> vulkan = vulkan_backend(engine);
  return check_function_form(engine, *vulkan, library, entry, target);
}

}  // namespace penumbra
