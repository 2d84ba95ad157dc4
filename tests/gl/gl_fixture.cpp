#include "gl_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/runtime/library_programs.hpp"

namespace penumbra::testing {

std::unique_ptr<GlEngine> make_gl_engine() {
  auto engine = GlEngine::create({}, ignore_diagnostics());
  if (!engine) {
    ADD_FAILURE() << "no GL engine: " << engine.error().to_string();
    return nullptr;
  }
  return std::move(*engine);
}

std::unique_ptr<Variant> default_variant(const std::string& name) {
  auto variants =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "default.json");
  if (!variants) {
    ADD_FAILURE() << variants.error().to_string();
    return nullptr;
  }
  for (Variant& variant : *variants) {
    if (variant.name == name) return std::make_unique<Variant>(std::move(variant));
  }
  ADD_FAILURE() << "permutations/default.json has no variant " << name;
  return nullptr;
}

Result<PassText> emitted_pass(const Variant& variant, Target target, PassKind kind) {
  auto pass = compile_pass(variant, target, kind);
  if (!pass) return pass.error();
  return PassText{std::move(pass->vert.text), std::move(pass->frag.text)};
}

Result<MinmaxText> emitted_minmax(const Variant& variant, Target target) {
  auto init = emitted_pass(variant, target, PassKind::minmax_init);
  if (!init) return init.error();
  auto reduce = emitted_pass(variant, target, PassKind::minmax_reduce);
  if (!reduce) return reduce.error();
  return MinmaxText{std::move(*init), std::move(*reduce)};
}

SceneInputs scene_inputs(const reference::Scene& scene) {
  SceneInputs inputs;
  inputs.scene = scene;
  inputs.linear_depth =
      reference::ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  const float depth_scale = depth_scale_for(scene.far_z);
  inputs.normalized_depth = inputs.linear_depth;
  for (float& d : inputs.normalized_depth.data) d *= depth_scale;  // exact: a power of two
  inputs.receivers = reference::receivers(scene, scene.receivers_width, scene.receivers_height);
  inputs.params = shadow_params(
      scene.light,
      {scene.map_width, scene.map_height, scene.receivers_width, scene.receivers_height},
      depth_scale);
  return inputs;
}

SceneInputs any_scene_inputs() {
  return scene_inputs(reference::builtin_scenes().front());
}

}  // namespace penumbra::testing
