#include "penumbra/verify/function_form.hpp"

#include <cmath>
#include <vector>

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
  const auto y0 = float(stage.ground_y[0]), y1 = float(stage.ground_y[1]);
  const auto z = float(stage.scene.plane_z0);
  const std::array<float, 3> corners[] = {{-h, y0, z}, {h, y0, z}, {h, y1, z}, {-h, y1, z}};
  for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(corners[k]);
  return out;
}

// How far the function's float32 clip_to_query() (common/light_clip.glsl)
// may put each receiver channel from the one derived exactly from the
// clip position it was called with (`clip`, as receivers_from_clip() takes
// it): x / w within 2.5 ulp, then 0.5 + 0.5 ndc rounded, u = 2^-24; z_r is
// w itself, or under an orthographic light the depth decoded from z / w,
// within 16 u of n + f.
FloatImage clip_error_bound(const FloatImage& clip, int w_channel, const LightClipDepth& depth) {
  constexpr double u = 0x1p-24;
  FloatImage out(clip.width, clip.height, 3);
  for (int j = 0; j < clip.height; ++j) {
    for (int i = 0; i < clip.width; ++i) {
      const double w = depth.orthographic ? 1.0 : clip.at(i, j, w_channel);
      if (!(clip.at(i, j, w_channel) > 0.0f)) continue;
      for (int c = 0; c < 2; ++c) {
        const double ndc = std::abs(clip.at(i, j, c) / w);
        out.at(i, j, c) = float(2.5 * u * ndc + u * (0.5 + 0.5 * ndc));
      }
      out.at(i, j, 2) =
          depth.orthographic
              ? float(16.0 * u * (std::abs(depth.near_plane) + std::abs(depth.far_plane)))
              : 0.0f;
    }
  }
  return out;
}

}  // namespace

Result<EngineFormCheck> check_function_form(Engine& engine, Backend& backend, CameraStages& stages,
                                            PictureReferences& references, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            std::optional<int> cascade) {
  const auto form = entry.function.find(target);
  if (form == entry.function.end()) {
    return make_error(
        Error::Kind::bad_input, entry.variant.name,
        "the library has no function form for target " + std::string(to_string(target)));
  }
  PENUMBRA_TRY_ASSIGN(const CameraStage* stage, stages.get(library, entry, target, cascade));
  const CameraStage& camera = *stage;
  EngineFormCheck check = started_check(entry, target, backend, cascade);
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
  draw.params = camera.fixture.params;
  if (camera.fixture.placed) {
    // An atlas or array variant's function takes its light at each call;
    // the block's members the call replaces are left zero, so that a
    // function that read them instead fails.
    std::optional<int> layer;
    if (camera.fixture.layout() == MapLayout::array) {
      layer = static_cast<int>(draw.params.at("map_layer")[0]);
    }
    draw.call = CallLight{draw.params.at("light"), draw.params.at("sampling"),
                          draw.params.at("map_tile"), layer};
    for (const char* member : {"light", "sampling", "map_tile", "map_layer"}) {
      draw.params[member] = {};
    }
  }
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
  // The function derived its receivers in float32: a back-projection's
  // patches move with their last bits (g(z) grows near an occluder).
  const auto rounded = [&] {
    return receiver_bounds(entry.variant, receivers, {}, {},
                           clip_error_bound(drawn.clip, 3, draw.light_depth));
  };
  PENUMBRA_TRY(judge_picture(check, engine, entry, camera, drawn.own_stored_depth, receivers,
                             drawn.clip, 2, rounded, &references));
  return check;
}

Result<EngineFormCheck> check_function_form(Engine& engine, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            DepthFormat map_format) {
  const std::unique_ptr<Backend> vulkan = vulkan_backend(engine);
  CameraStages stages(engine, map_format);
  PictureReferences references;
  return check_function_form(engine, *vulkan, stages, references, library, entry, target, {});
}

}  // namespace penumbra
