#include "penumbra/verify/pictures.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <map>
#include <mutex>

#include "backend.hpp"
#include "cpu_work.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
#include "progress_counter.hpp"
#include "scene_fixture.hpp"
#include "scene_truths.hpp"

namespace penumbra {
namespace {

bool wanted(const std::vector<Target>& targets, Target target) {
  return targets.empty() || std::find(targets.begin(), targets.end(), target) != targets.end();
}

bool wanted(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
}

// The scene prepared for one target and map encoding by the depth (and
// min-max) passes of the first variant that needs them, as verify prepares
// its scenes.
class TargetStages {
 public:
  TargetStages(const Library& library, Engine& engine, const PictureScene& scene)
      : library_(library), engine_(engine), scene_(scene) {}

  Result<const TargetScenes*> get(const LibraryVariant& entry, Target target) {
    const auto key = std::pair(target, map_encoding(entry.variant.keys));
    auto it = prepared_.find(key);
    if (it == prepared_.end()) it = prepared_.emplace(key, prepare(entry, target)).first;
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
    PENUMBRA_TRY_ASSIGN(auto fixture, prepare_scene(engine_, truths_, depth.program, target,
                                                    scene_.scene, scene_.receivers));
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
  SceneTruths truths_;  // the scene's ray cast, once for every target
  std::map<std::pair<Target, MapEncoding>, Result<TargetScenes>> prepared_;
};

// A map a path drew itself (SceneOutput): as stored and as linear z.
struct OwnMap {
  std::shared_ptr<const FloatImage> stored;
  std::shared_ptr<const FloatImage> linear;
};

// The CPU reference of what the run shows (after screen passes that filter
// it, the reference factor filtered, every pixel decided), on the map the target's own depth
// pass rendered (the fixture's, or the path's own), as stored and linear.
Result<reference::ReferenceImage> reference_image(const Variant& variant, Target target,
                                                  const SceneFixture& fixture,
                                                  const FloatImage& stored,
                                                  const FloatImage& linear,
                                                  const reference::SamplingPrecision& precision) {
  PENUMBRA_TRY_ASSIGN(auto expected, reference_on_map(variant, fixture, stored, linear, precision,
                                                      reference::shader_limits(target)));
  if (!reference::filters_screen(variant.technique)) return expected;
  FloatImage blurred =
      reference::screen_visibility(variant, std::move(expected.visibility), fixture.receivers);
  FloatImage none(blurred.width, blurred.height, 1);
  return reference::ReferenceImage{blurred, std::move(none), blurred, blurred};
}

// `own_map`: the path's own map, when it draws one (SceneOutput).
Status run_passes(PictureRun& run, const LoadedPasses& passes, const SceneFixture& fixture,
                  int timed_runs, OwnMap& own_map) {
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
    own_map = {std::move(output.own_stored_depth), std::move(output.own_linear_depth)};
  }
  return {};
}

}  // namespace

namespace {

// One (variant, target)'s runs on every path, the device's part done; the
// CPU's part (the references, the sink) is one job.
struct PendingPictures {
  std::vector<PictureRun> runs;
  std::vector<OwnMap> own_maps;           // per run; null: the fixture's
  const SceneFixture* fixture = nullptr;  // null when no run executed
};

// The references of `pending`'s runs (the fixture's computed once), then
// each run to the sink. A run whose reference fails is handed on failed.
// Returns the first error of the sink, with its run's order.
std::optional<std::pair<std::size_t, Error>> finish_pictures(
    PendingPictures& pending, const Variant& variant, Target target,
    const reference::SamplingPrecision& precision, const PictureSink& sink,
    ProgressCounter& progress) {
  std::optional<Result<reference::ReferenceImage>> on_fixture;
  std::optional<std::pair<std::size_t, Error>> failed;
  for (std::size_t r = 0; r < pending.runs.size(); ++r) {
    PictureRun& run = pending.runs[r];
    if (run.not_executed.empty() && run.error.empty()) {
      const SceneFixture& fixture = *pending.fixture;
      const OwnMap& own_map = pending.own_maps[r];
      Result<reference::ReferenceImage> own =
          own_map.linear ? reference_image(variant, target, fixture, *own_map.stored,
                                           *own_map.linear, precision)
                         : Result<reference::ReferenceImage>(reference::ReferenceImage{});
      if (!own_map.linear && !on_fixture) {
        on_fixture = reference_image(variant, target, fixture, fixture.normalized_depth,
                                     fixture.linear_depth, precision);
      }
      const Result<reference::ReferenceImage>& expected = own_map.linear ? own : *on_fixture;
      if (expected) {
        run.reference = expected->visibility;
        run.reference_ambiguous = expected->ambiguous;
      } else {
        run.error = expected.error().to_string();
        run.visibility = run.texel_reads = FloatImage();
      }
    }
    const std::string unit =
        run.variant + " [" + std::string(to_string(run.target)) + " on " + run.backend + "]";
    const std::size_t order = run.order;
    if (Status s = sink(std::move(run)); !s && !failed) failed.emplace(order, s.error());
    progress.finished(unit);
  }
  return failed;
}

// The runs render_pictures() makes: the progress's total.
std::size_t count_runs(const Library& library, const PictureOptions& options,
                       const std::vector<std::unique_ptr<Backend>>& backends) {
  std::size_t runs = 0;
  for (const LibraryVariant& entry : library.variants) {
    if (!wanted(options.variants, entry.variant.name)) continue;
    for (Target target : entry.variant.targets) {
      if (!wanted(options.targets, target)) continue;
      for (const auto& backend : backends) runs += backend->executes(target) ? 1 : 0;
    }
  }
  return runs;
}

}  // namespace

std::string off_stage(const Variant& variant) {
  if (!is_orthographic(map_encoding(variant.keys))) return {};
  return "the pictures' stage has a perspective light; verify checks orthographic maps on its "
         "directional one";
}

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
  const auto backends = all_backends(engine, shared_runs(options.bytecode), options.skipped);
  TargetStages stages(library, engine, scene);
  ProgressCounter progress(options.progress, count_runs(library, options, backends));
  // Each job's first failure; the earliest run's is returned.
  std::mutex failures_mutex;
  std::vector<std::pair<std::size_t, Error>> failures;
  std::atomic<bool> stop{false};
  std::deque<PendingPictures> pending;  // stable addresses for the jobs
  std::size_t order = 0;

  CpuWork work(options.jobs);
  work.run([&] {
    for (const LibraryVariant& entry : library.variants) {
      const Variant& variant = entry.variant;
      if (!wanted(options.variants, variant.name)) continue;
      for (Target target : variant.targets) {
        if (!wanted(options.targets, target) || stop) continue;
        PendingPictures& pictures = pending.emplace_back();
        for (const std::unique_ptr<Backend>& backend : backends) {
          if (!backend->executes(target)) continue;
          PictureRun& run = pictures.runs.emplace_back();
          OwnMap& own_map = pictures.own_maps.emplace_back();
          run.order = order++;
          run.variant = variant.name;
          run.technique = variant.technique;
          run.target = target;
          run.backend = backend->name();
          run.not_executed = backend->missing();
          if (run.not_executed.empty()) run.not_executed = backend->not_executed(entry, target);
          if (run.not_executed.empty()) run.not_executed = off_stage(variant);
          if (run.not_executed.empty()) run.not_executed = form_not_built(variant, Form::query);
          if (!run.not_executed.empty()) continue;
          Status ran = [&]() -> Status {
            PENUMBRA_TRY_ASSIGN(const TargetScenes* scenes, stages.get(entry, target));
            pictures.fixture = &scenes->scenes.front();
            PENUMBRA_TRY_ASSIGN(auto passes, backend->load(library, entry, target, *scenes));
            run.device = backend->device();
            return run_passes(run, passes, *pictures.fixture, options.timed_runs, own_map);
          }();
          if (!ran) {
            run.error = ran.error().to_string();
            run.visibility = run.texel_reads = FloatImage();
          }
        }
        work.submit([&, &variant = variant, target] {
          auto failed = finish_pictures(pictures, variant, target, precision, sink, progress);
          pictures = {};  // its images are written: free them
          if (!failed) return;
          stop = true;
          const std::lock_guard lock(failures_mutex);
          failures.push_back(std::move(*failed));
        });
      }
      diagnostics({Severity::note, variant.name, "pictured"});
    }
    work.wait();
  });
  if (failures.empty()) return {};
  return std::min_element(failures.begin(), failures.end(),
                          [](const auto& a, const auto& b) { return a.first < b.first; })
      ->second;
}

}  // namespace penumbra
