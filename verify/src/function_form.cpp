#include "penumbra/verify/function_form.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine_shaders.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/support/file.hpp"
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

// (u, v, z_r) from each pixel's light clip position, as the function form
// derives them on `target` (docs/function-form.md); a pixel no surface
// covers (w = 0, the clear) gets a receiver at the light, which is lit.
FloatImage receivers_of(const FloatImage& clip, Target target) {
  const double v_sign = traits(target).is_hlsl ? -0.5 : 0.5;
  FloatImage out(clip.width, clip.height, 3);
  for (int j = 0; j < clip.height; ++j) {
    for (int i = 0; i < clip.width; ++i) {
      const double w = clip.at(i, j, 3);
      if (!(w > 0.0)) {
        out.at(i, j, 0) = out.at(i, j, 1) = 0.5f;
        out.at(i, j, 2) = 0.0f;
        continue;
      }
      out.at(i, j, 0) = float(0.5 + 0.5 * (clip.at(i, j, 0) / w));
      out.at(i, j, 1) = float(0.5 + v_sign * (clip.at(i, j, 1) / w));
      out.at(i, j, 2) = float(w);
    }
  }
  return out;
}

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

// Whether pixel (i, j) lies inside one face of the stage with the rest of
// its 2x2 quad, the pixels a GPU takes screen derivatives over: each drawn
// (w > 0) and on the same face in the ray cast. Elsewhere the GPU's
// derivatives extrapolate a face past its edge, and rasterization and the
// ray cast may see different surfaces.
bool inside_face(const reference::Stage& stage, const reference::StageView& view,
                 const FloatImage& receivers, int i, int j) {
  const auto face = [&](int x, int y) {
    const std::size_t k = std::size_t(y) * receivers.width + x;
    return receivers.at(x, y, 2) > 0.0f ? face_of(stage.scene, view.points[k], view.surfaces[k])
                                        : -1;
  };
  const int own = face(i, j);
  if (own < 0) return false;
  const int qi = i & ~1, qj = j & ~1;
  for (int dj = 0; dj < 2; ++dj) {
    for (int di = 0; di < 2; ++di) {
      const int x = std::min(qi + di, receivers.width - 1);
      const int y = std::min(qj + dj, receivers.height - 1);
      if (face(x, y) != own) return false;
    }
  }
  return true;
}

// See FunctionFormCheck::camera_agreement.
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

}  // namespace

Result<FunctionFormCheck> check_function_form(Engine& engine, const Library& library,
                                              const LibraryVariant& entry, Target target) {
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
  PENUMBRA_TRY_ASSIGN(const std::string text, read_file(library.root / form->second.file));
  const std::string vertex = engine_vertex_shader(target, camera_clip(stage, width, height, target),
                                                  light_clip(scene.light, target));
  PassProgram program;
  program.target = target;
  program.reflection = form->second.reflection;
  // The engine's own vertex input, render target and depth buffer: the
  // depth pass's position and depth format, and four floats.
  program.reflection.vertex_inputs = depth.program.reflection.vertex_inputs;
  program.reflection.depth_target = depth.program.reflection.depth_target;
  program.reflection.render_targets = {
      {"colour", 0, std::string(api_format(target, TextureFormat::rgba32_float))}};
  program.d3d_viewport = traits(target).is_hlsl;
  program.gl_clip_depth = !traits(target).is_hlsl;
  PENUMBRA_TRY_ASSIGN(program.vert, compile_text_stage(target, ShaderStage::vertex, vertex,
                                                       form->second.file + " (engine vertex stage)",
                                                       check.execution));
  const std::string fragment = engine_fragment_shader(target, form->second.reflection, text);
  PENUMBRA_TRY_ASSIGN(
      program.frag,
      compile_text_stage(target, ShaderStage::fragment, fragment,
                         form->second.file + " (engine fragment stage)", check.execution));
  // (x, y, visibility, w) per pixel; the background keeps the clear, 1.
  PENUMBRA_TRY_ASSIGN(const FloatImage clip,
                      engine.run_surface(program, stage_triangles(stage), *fixture.map, width,
                                         height, fixture.params));

  fixture.receivers = receivers_of(clip, target);
  check.camera_agreement = camera_agreement(view, fixture.receivers);
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, engine.device_info().sub_texel_precision_bits))};
  PENUMBRA_TRY_ASSIGN(
      const reference::ReferenceImage expected,
      reference_on_map(entry.variant, fixture, fixture.normalized_depth, fixture.linear_depth,
                       precision, reference::shader_limits(target)));
  // The pixels inside a face, in a row: the GPU's visibility (output
  // 0's z), the reference's and its ambiguity.
  std::vector<std::size_t> inside;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      if (inside_face(stage, view, fixture.receivers, i, j))
        inside.push_back(std::size_t(j) * width + i);
    }
  }
  const int count = int(inside.size());
  FloatImage gpu(count, 1, 1), reference(count, 1, 1), ambiguous(count, 1, 1);
  for (std::size_t k = 0; k < inside.size(); ++k) {
    gpu.data[k] = clip.data[4 * inside[k] + 2];
    reference.data[k] = expected.visibility.data[inside[k]];
    ambiguous.data[k] = expected.ambiguous.data[inside[k]];
  }
  check.surface_pixels = inside.size();
  PENUMBRA_TRY_ASSIGN(check.comparison,
                      reference::compare(gpu, reference, ambiguous,
                                         reference::tolerance(entry.variant.technique, precision)));
  check.pass = check.comparison.pass && check.camera_agreement >= kMinCameraAgreement;
  return check;
}

}  // namespace penumbra
