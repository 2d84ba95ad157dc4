#include "gl_fixture.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <mutex>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/library.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/verify/shadow_params.hpp"
#include "penumbra/vulkan/library_programs.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

// Libraries of one variant each, built on first use under one temporary
// directory that goes with the test process.
class BuiltLibraries {
 public:
  ~BuiltLibraries() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }

  Result<const Library*> get(const Variant& variant) {
    const std::lock_guard lock(mutex_);
    if (const auto found = built_.find(variant.name); found != built_.end()) {
      return &found->second;
    }
    Variant glsl = variant;
    glsl.targets = {Target::glsl330, Target::glsl450};
    const fs::path out = root_ / variant.name;
    auto summary = build_library({&glsl, 1}, out, BuildOptions{.jobs = 2}, ignore_diagnostics());
    if (!summary) return summary.error();
    auto library = load_library(out);
    if (!library) return library.error();
    return &built_.emplace(variant.name, std::move(*library)).first->second;
  }

 private:
  fs::path root_ = fs::temp_directory_path() / ("penumbra_gl_tests_" + std::to_string(::getpid()));
  std::mutex mutex_;
  std::map<std::string, Library> built_;
};

BuiltLibraries& built_libraries() {
  static BuiltLibraries libraries;
  return libraries;
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
  auto library = built_libraries().get(variant);
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
