#include "penumbra/verify/function_form.hpp"

#include "backend.hpp"
#include "camera_stage.hpp"
#include "engine_shaders.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/support/file.hpp"

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

Result<EngineFormCheck> check_function_form(Engine& engine, Backend& backend,
                                            const Library& library, const LibraryVariant& entry,
                                            Target target, DepthFormat map_format) {
  const auto form = entry.function.find(target);
  if (form == entry.function.end()) {
    return make_error(
        Error::Kind::bad_input, entry.variant.name,
        "the library has no function form for target " + std::string(to_string(target)));
  }
  PENUMBRA_TRY_ASSIGN(CameraStage camera, camera_stage(engine, library, entry, target, map_format));
  EngineFormCheck check = started_check(entry, target, backend);
  PENUMBRA_TRY_ASSIGN(const std::string text, read_file(library.root / form->second.file));
  SurfaceDraw draw;
  draw.library = &library;
  draw.entry = &entry;
  draw.target = target;
  draw.where = form->second.file;
  draw.camera = camera_clip(camera.stage, camera.width, camera.height, target);
  draw.light_depth = light_clip_depth(camera.stage.scene.light, camera.fixture.far_plane(), target);
  draw.light = light_clip(camera.stage.scene.light, draw.light_depth, target);
  draw.vertex = {takes_pixel(form->second.reflection), camera.width, camera.height};
  draw.function_text = text;
  // The engine's own vertex input, render target and depth buffer: the
  // depth pass's position and depth format, and four floats.
  draw.reflection = form->second.reflection;
  draw.reflection.vertex_inputs = camera.depth.vertex_inputs;
  draw.reflection.depth_target = camera.depth.depth_target;
  draw.reflection.render_targets = {
      {"colour", 0, std::string(api_format(target, TextureFormat::rgba32_float))}};
  draw.triangles = stage_triangles(camera.stage);
  draw.width = camera.width;
  draw.height = camera.height;
  // (x, y, visibility, w) per pixel; the background keeps the clear, 1.
  PENUMBRA_TRY_ASSIGN(const SurfacePicture drawn,
                      backend.draw_surface(draw, camera.fixture, check.execution));
  const FloatImage receivers = receivers_from_clip(
      drawn.clip, 3, traits(target).is_hlsl ? -0.5 : 0.5, draw.light_depth.orthographic);
  PENUMBRA_TRY(judge_picture(check, engine, entry, camera, drawn.own_stored_depth, receivers,
                             drawn.clip, 2));
  return check;
}

Result<EngineFormCheck> check_function_form(Engine& engine, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            DepthFormat map_format) {
  const std::unique_ptr<Backend> vulkan = vulkan_backend(engine);
  return check_function_form(engine, *vulkan, library, entry, target, map_format);
}

}  // namespace penumbra
