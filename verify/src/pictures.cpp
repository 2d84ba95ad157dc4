#include "penumbra/verify/pictures.hpp"

#include <algorithm>
#include <chrono>
#include <map>

#include "backend.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "scene_fixture.hpp"

namespace penumbra {
namespace {

bool wanted(const std::vector<Target>& targets, Target target) {
  return targets.empty() || std::find(targets.begin(), targets.end(), target) != targets.end();
}

// The scene prepared for one target by the depth (and min-max) passes of
// the first variant that needs them, as verify prepares its scenes.
class TargetStages {
 public:
  TargetStages(const Library& library, Engine& engine, const PictureScene& scene)
      : library_(library), engine_(engine), scene_(scene) {}

  Result<const TargetScenes*> get(const LibraryVariant& entry, Target target) {
    auto it = prepared_.find(target);
    if (it == prepared_.end()) it = prepared_.emplace(target, prepare(entry, target)).first;
    Result<TargetScenes>& prepared = it->second;
    if (!prepared) return prepared.error();
    if (uses_minmax_mip(entry.variant.technique) && !prepared->minmax) {
      prepared->minmax = build_minmax(entry, target, prepared->scenes.front());
    }
    return &*prepared;
  }

 private:
  Result<TargetScenes> prepare(const LibraryVariant& entry, Target target) {
    PENUMBRA_TRY_ASSIGN(auto depth, load_executable(library_, entry, PassKind::depth, target));
    PENUMBRA_TRY_ASSIGN(auto fixture, prepare_scene(engine_, depth.program, target, scene_.scene,
                                                    scene_.receivers));
    TargetScenes scenes;
    scenes.scenes.push_back(std::move(fixture));
    return scenes;
  }

  Status build_minmax(const LibraryVariant& entry, Target target, SceneFixture& fixture) {
    PENUMBRA_TRY_ASSIGN(auto init, load_executable(library_, entry, PassKind::minmax_init, target));
    PENUMBRA_TRY_ASSIGN(auto reduce,
                        load_executable(library_, entry, PassKind::minmax_reduce, target));
    PENUMBRA_TRY(engine_.build_minmax(*fixture.map, init.program, reduce.program, fixture.params));
    return {};
  }

  const Library& library_;
  Engine& engine_;
  const PictureScene& scene_;
  std::map<Target, Result<TargetScenes>> prepared_;
};

// The CPU reference of what the run shows (screen_blur: the reference
// factor blurred, every pixel decided), on `linear_depth`: the map the
// target's own depth pass rendered (the fixture's, or the path's own).
Result<reference::ReferenceImage> reference_image(const Variant& variant, Target target,
                                                  const SceneFixture& fixture,
                                                  const FloatImage& linear_depth,
                                                  const reference::SamplingPrecision& precision) {
  PENUMBRA_TRY_ASSIGN(
      auto expected,
      reference::evaluate_image(variant, linear_depth, fixture.scene.light, fixture.receivers,
                                precision, reference::shader_limits(target)));
  if (variant.technique != Technique::screen_blur) return expected;
  FloatImage blurred = reference::screen_blur(variant, expected.visibility, fixture.receivers);
  FloatImage none(blurred.width, blurred.height, 1);
  return reference::ReferenceImage{std::move(blurred), std::move(none)};
}

// `own_map`: the path's own map, when it draws one (SceneOutput).
Status run_passes(PictureRun& run, const LoadedPasses& passes, const SceneFixture& fixture,
                  int timed_runs, std::shared_ptr<const FloatImage>& own_map) {
  run.execution = passes.execution;
  run.run_seconds = 0.0;
  for (int i = 0; i < std::max(1, timed_runs); ++i) {
    const auto start = std::chrono::steady_clock::now();
    PENUMBRA_TRY_ASSIGN(SceneOutput output, passes.run(fixture));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (i == 0 || seconds < run.run_seconds) run.run_seconds = seconds;
    run.visibility = output.chain ? std::move(output.chain->blurred) : std::move(output.visibility);
    run.texel_reads = std::move(output.texel_reads);
    own_map = std::move(output.own_linear_depth);
  }
  return {};
}

}  // namespace

Status render_pictures(const Library& library, Engine& engine, const PictureScene& scene,
                       const PictureOptions& options, const PictureSink& sink,
                       const DiagnosticConsumer& diagnostics) {
  for (const std::string& name : options.variants) {
    if (!library.find(name)) {
      return make_error(Error::Kind::bad_input, name,
                        "no such variant in " + library.root.string());
    }
  }
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, engine.device_info().sub_texel_precision_bits))};
  const auto backends = all_backends(engine, options.bytecode, options.gl, options.wine);
  TargetStages stages(library, engine, scene);

  for (const LibraryVariant& entry : library.variants) {
    const Variant& variant = entry.variant;
    if (!options.variants.empty() && std::find(options.variants.begin(), options.variants.end(),
                                               variant.name) == options.variants.end()) {
      continue;
    }
    for (Target target : variant.targets) {
      if (!wanted(options.targets, target)) continue;
      // The reference depends on the target (its shader limits), not the path.
      std::optional<Result<reference::ReferenceImage>> expected;
      for (const std::unique_ptr<Backend>& backend : backends) {
        if (!backend->executes(target)) continue;
        PictureRun run;
        run.variant = variant.name;
        run.technique = variant.technique;
        run.target = target;
        run.backend = backend->name();
        run.not_executed = backend->missing();
        if (run.not_executed.empty()) run.not_executed = backend->not_executed(entry, target);
        if (run.not_executed.empty()) {
          Status ran = [&]() -> Status {
            PENUMBRA_TRY_ASSIGN(const TargetScenes* scenes, stages.get(entry, target));
            const SceneFixture& fixture = scenes->scenes.front();
            PENUMBRA_TRY_ASSIGN(auto passes, backend->load(library, entry, target, *scenes));
            run.device = backend->device();
            std::shared_ptr<const FloatImage> own_map;
            PENUMBRA_TRY(run_passes(run, passes, fixture, options.timed_runs, own_map));
            if (own_map) {
              PENUMBRA_TRY_ASSIGN(auto own,
                                  reference_image(variant, target, fixture, *own_map, precision));
              run.reference = std::move(own.visibility);
              run.reference_ambiguous = std::move(own.ambiguous);
              return {};
            }
            if (!expected) {
              expected = reference_image(variant, target, fixture, fixture.linear_depth, precision);
            }
            if (!*expected) return expected->error();
            run.reference = (*expected)->visibility;
            run.reference_ambiguous = (*expected)->ambiguous;
            return {};
          }();
          if (!ran) {
            run.error = ran.error().to_string();
            run.visibility = run.reference = run.reference_ambiguous = run.texel_reads =
                FloatImage();
          }
        }
        PENUMBRA_TRY(sink(std::move(run)));
      }
    }
    diagnostics({Severity::note, variant.name, "pictured"});
  }
  return {};
}

}  // namespace penumbra
