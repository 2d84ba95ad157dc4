#include "gl_fixture.hpp"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <mutex>

#include "default_library.hpp"
#include "penumbra/library/pass_files.hpp"
#include "penumbra/model/shadow_params.hpp"

namespace penumbra::testing {
namespace {

// The library of `variant` for both GLSL targets, built on first use and
// kept until the test process ends.
Result<const Library*> glsl_library(const Variant& variant) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<TemporaryLibrary>> built;
  const std::lock_guard lock(mutex);
  if (const auto found = built.find(variant.name); found != built.end()) {
    return &found->second->library();
  }
  auto library =
      TemporaryLibrary::build({variant}, {Target::glsl330, Target::glsl450}, {.jobs = 2});
  if (!library) return library.error();
  return &built.emplace(variant.name, std::move(*library)).first->second->library();
}

}  // namespace

std::unique_ptr<GlEngine> make_gl_engine() {
  auto engine = GlEngine::create({}, ignore_diagnostics());
  if (!engine) {
    ADD_FAILURE() << "no GL engine: " << engine.error().to_string();
    return nullptr;
  }
  return std::move(*engine);
}

Result<PassText> emitted_pass(const Variant& variant, Target target, PassKind kind) {
  auto library = glsl_library(variant);
  if (!library) return library.error();
  const LibraryVariant* entry = (*library)->find(variant.name);
  if (entry == nullptr || !entry->reflection.contains(kind) ||
      !entry->reflection.at(kind).contains(target)) {
    return make_error(Error::Kind::internal, variant.name,
                      "the built library has no reflection." + std::string(to_string(kind)) + "." +
                          std::string(to_string(target)));
  }
  auto vert = read_pass_file(**library, *entry, kind, target, ShaderStage::vertex);
  if (!vert) return vert.error();
  auto frag = read_pass_file(**library, *entry, kind, target, ShaderStage::fragment);
  if (!frag) return frag.error();
  return PassText{std::move(*vert), std::move(*frag), entry->reflection.at(kind).at(target)};
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
