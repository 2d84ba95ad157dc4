#include <algorithm>
#include <chrono>
#include <latch>
#include <map>
#include <set>
#include <thread>
#include <tuple>

#include "backend.hpp"
#include "camera_stage.hpp"
#include "cpu_work.hpp"
#include "map_placement.hpp"
#include "minmax_check.hpp"
#include "pair_queue.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/stage_picture.hpp"
#include "penumbra/verify/verify.hpp"
#include "progress_counter.hpp"
#include "scene_checks.hpp"
#include "scene_fixture.hpp"
#include "scene_truths.hpp"
#include "verify_plan.hpp"

namespace penumbra {
namespace {

// The checks one pair adds beside its runs, gathered in plan order at the
// end whichever device thread ran it.
struct PairChecks {
  std::vector<DepthCheck> depth_checks;
  std::vector<MinmaxCheck> minmax_checks;
  std::vector<EngineFormCheck> function_checks;
  std::vector<EngineFormCheck> deferred_checks;
};

struct PairResult {
  std::unique_ptr<PendingTarget> runs;
  PairChecks checks;
};

// One device thread's devices and what it has drawn on them.
struct Context {
  const Library& library;
  Engine& engine;  // prepares every target's scenes
  reference::SamplingPrecision precision;
  SceneTruths& truths;  // every target's ray casts, shared by the device threads
  // The paths every run goes through, in report order.
  std::vector<std::unique_ptr<Backend>> backends{};
  std::map<MapKey, TargetScenes> scenes{};
  // Maps whose depth pass could not run: every run on them fails with this.
  std::map<MapKey, Error> broken_targets{};
  DepthFormat map_format = DepthFormat::d32_float;  // VerifyOptions::map_format
  CameraStages cameras;                             // the engine-form checks' stage, per depth pass
};

// `entry`'s function form or deferred pass (`check`) for `target` on
// `backend`; one that cannot run fails with why.
using EngineFormChecker = Result<EngineFormCheck> (*)(Engine&, Backend&, CameraStages&,
                                                      PictureReferences&, const Library&,
                                                      const LibraryVariant&, Target,
                                                      std::optional<int>);
EngineFormCheck run_engine_form(Context& ctx, EngineFormChecker checker, Backend& backend,
                                PictureReferences& references, const LibraryVariant& entry,
                                Target target, std::optional<int> cascade) {
  const auto start = Clock::now();
  auto check =
      checker(ctx.engine, backend, ctx.cameras, references, ctx.library, entry, target, cascade);
  EngineFormCheck out = check ? std::move(*check) : EngineFormCheck{};
  if (!check) {
    out.variant = entry.variant.name;
    out.target = target;
    out.backend = backend.name();
    out.cascade = cascade;
    out.error = check.error().to_string();
  }
  out.seconds = seconds_since(start);
  return out;
}

// The scenes `entry` reads: `scenes`, or for an atlas or array variant
// their maps placed so (made ready by run_pair()).
const TargetScenes& variant_scenes(const TargetScenes& scenes, const LibraryVariant& entry) {
  const MapLayout layout = map_layout(entry.variant.keys);
  return layout == MapLayout::single ? scenes : *scenes.placed.at(layout);
}

// Every scene of `scenes` with its map placed as `layout` reads it, on
// `engine`. The min-max mip is not built on them: no such variant reads it.
Result<std::shared_ptr<TargetScenes>> prepare_placed(Engine& engine, const TargetScenes& scenes,
                                                     MapLayout layout) {
  auto out = std::make_shared<TargetScenes>();
  for (const SceneFixture& fixture : scenes.scenes) {
    PENUMBRA_TRY_ASSIGN(SceneFixture placed,
                        placed_fixture(engine, fixture, scene_placement(layout)));
    out->scenes.push_back(std::move(placed));
  }
  return out;
}

// `entry`'s passes for `target` on `backend`, on the device: every scene's
// output, to be checked. A run that cannot load or execute is failed here.
PendingRun run_on_device(Context& ctx, Backend& backend, const LibraryVariant& entry, Target target,
                         PairChecks& report) {
  const auto start = Clock::now();
  PendingRun pending;
  TargetRun& run = pending.run;
  run.target = target;
  run.backend = backend.name();
  if (std::string missing = backend.missing(); !missing.empty()) {
    run.not_executed = std::move(missing);
    return pending;
  }
  if (std::string lacking = backend.not_executed(entry, target); !lacking.empty()) {
    run.not_executed = std::move(lacking);
    return pending;
  }
  if (std::string lacking = form_not_built(entry.variant, Form::query); !lacking.empty()) {
    run.not_executed = std::move(lacking);  // the engine forms are checked without it
    return pending;
  }
  const TargetScenes& scenes = variant_scenes(ctx.scenes.at(map_key(entry.variant, target)), entry);
  auto passes = backend.load(ctx.library, entry, target, scenes);
  if (!passes) {
    run = failed_run(target, backend.name(), passes.error());
    run.seconds = seconds_since(start);
    return pending;
  }
  run.device = backend.device();
  run.execution = passes->execution;
  run.executed = true;
  for (const SceneFixture& fixture : scenes.scenes) {
    const auto scene_start = Clock::now();
    auto gpu = passes->run(fixture);
    if (!gpu) {
      run = failed_run(target, backend.name(), gpu.error());
      pending.outputs.clear();
      break;
    }
    if (gpu->own_depth_check) report.depth_checks.push_back(*gpu->own_depth_check);
    pending.outputs.push_back(std::move(*gpu));
    pending.device_seconds.push_back(seconds_since(scene_start));
  }
  run.seconds = seconds_since(start);
  pending.checked.resize(pending.outputs.size(), Result<SceneRun>(SceneRun{}));
  pending.check_seconds.resize(pending.outputs.size(), 0.0);
  return pending;
}

// Renders every scene with `target`'s depth pass (shared by all variants of
// a map encoding), taken from `entry`, a variant that has the target.
Status prepare_target(Context& ctx, const LibraryVariant& entry, Target target,
                      PairChecks& report) {
  auto depth = load_executable(ctx.library, entry, PassKind::depth, target);
  if (!depth) return depth.error();
  TargetScenes scenes;
  for (const reference::Scene& builtin : reference::builtin_scenes()) {
    const auto start = Clock::now();
    // An orthographic map's scenes are lit by a directional light.
    const reference::Scene scene =
        reference::for_map_encoding(builtin, map_encoding(entry.variant.keys));
    auto fixture = prepare_scene(
        ctx.engine, ctx.truths, depth->program, target, scene,
        reference::receivers(scene, scene.receivers_width, scene.receivers_height), ctx.map_format);
    if (!fixture) return fixture.error();
    report.depth_checks.push_back(fixture->depth_check);
    report.depth_checks.back().seconds = seconds_since(start);
    scenes.scenes.push_back(std::move(*fixture));
  }
  ctx.scenes.emplace(map_key(entry.variant, target), std::move(scenes));
  return {};
}

// Builds the min-max mip on every scene's map of `target` with the target's
// own minmax passes (shared by all variants), taken from `entry`, a variant
// that has them, and checks each against the CPU mip.
Status prepare_minmax(Context& ctx, const LibraryVariant& entry, Target target,
                      PairChecks& report) {
  auto init = load_executable(ctx.library, entry, PassKind::minmax_init, target);
  if (!init) return init.error();
  auto reduce = load_executable(ctx.library, entry, PassKind::minmax_reduce, target);
  if (!reduce) return reduce.error();
  for (SceneFixture& fixture : ctx.scenes.at(map_key(entry.variant, target)).scenes) {
    const auto start = Clock::now();
    auto built =
        ctx.engine.build_minmax(*fixture.map, init->program, reduce->program, fixture.params);
    auto levels = built ? ctx.engine.read_minmax(*fixture.map)
                        : Result<std::vector<FloatImage>>(built.error());
    if (!levels) {
      MinmaxCheck failed;
      failed.scene = fixture.scene.name;
      failed.target = target;
      failed.map_encoding = map_encoding(entry.variant.keys);
      failed.error = levels.error().to_string();
      failed.seconds = seconds_since(start);
      report.minmax_checks.push_back(std::move(failed));
      return levels.error();
    }
    report.minmax_checks.push_back(check_minmax(fixture, target, *levels));
    report.minmax_checks.back().seconds = seconds_since(start);
  }
  return {};
}

// `entry`'s function form and deferred pass for `target` on each path the
// plan runs that can draw them, each picture's reference evaluated once
// for all the paths that drew the same inputs.
void run_engine_forms(Context& ctx, const VerifyPlan& plan, const LibraryVariant& entry,
                      Target target, PairChecks& report) {
  PictureReferences references;
  const std::vector<std::optional<int>> stages = engine_form_stages(entry.variant);
  for (const std::optional<int>& cascade : stages) {
    for (const std::unique_ptr<Backend>& backend : ctx.backends) {
      if (!entry.function.contains(target) || !backend->draws_surfaces(target) ||
          !backend->missing().empty() || !plan.runs_path(backend->name())) {
        continue;
      }
      report.function_checks.push_back(
          run_engine_form(ctx, check_function_form, *backend, references, entry, target, cascade));
    }
  }
  for (const std::optional<int>& cascade : stages) {
    for (const std::unique_ptr<Backend>& backend : ctx.backends) {
      if (!runs_pass(PassKind::deferred, entry.variant) || !backend->executes(target) ||
          !backend->missing().empty() || !backend->not_executed(entry, target).empty() ||
          !plan.runs_path(backend->name())) {
        continue;
      }
      report.deferred_checks.push_back(
          run_engine_form(ctx, check_deferred_mask, *backend, references, entry, target, cascade));
    }
  }
}

// Starts, without waiting, the devices of `target`'s paths that take
// seconds to start (Backend::expect()).
void expect(Context& ctx, const VerifyPlan& plan, Target target) {
  for (const std::unique_ptr<Backend>& backend : ctx.backends) {
    if (backend->executes(target) && plan.runs_path(backend->name())) backend->expect(target);
  }
}

// The claimed pair on every path the plan runs: its target's maps (and
// min-max mip) prepared first where no earlier pair of this thread did, its
// runs on the devices, its engine forms, and its scenes' checks handed to
// `work`. A preparation's checks are kept where the claim reports them.
PairResult run_pair(Context& ctx, const VerifyPlan& plan, const PairQueue::Claim& claim,
                    CpuWork& work, ProgressCounter& progress) {
  const PlannedPair& pair = plan.variants[claim.variant].pairs[claim.pair];
  const LibraryVariant& entry = ctx.library.variants[plan.variants[claim.variant].index];
  const Target target = pair.target;
  const MapKey& key = pair.maps;
  PairResult result{std::make_unique<PendingTarget>(), {}};
  PairChecks unreported;      // an earlier pair's, on another device thread
  expect(ctx, plan, target);  // a pair of another thread's target
  if (!ctx.scenes.contains(key) && !ctx.broken_targets.contains(key)) {
    // A depth pass that cannot run fails every run of its target, not verify.
    const LibraryVariant& preparer = ctx.library.variants[pair.depth_preparer];
    if (Status s =
            prepare_target(ctx, preparer, target, claim.reports_maps ? result.checks : unreported);
        !s) {
      ctx.broken_targets.emplace(key, s.error());
    }
  }
  PendingTarget& target_runs = *result.runs;
  target_runs.label = entry.variant.name + " [" + std::string(to_string(target)) + "]";
  if (auto broken = ctx.broken_targets.find(key); broken != ctx.broken_targets.end()) {
    // Reported once, on the path that prepares the scenes.
    target_runs.runs.push_back(
        {failed_run(target, ctx.backends.front()->name(), broken->second), {}, {}, {}, {}});
    progress.finished(target_runs.label);
    return result;
  }
  TargetScenes& scenes = ctx.scenes.at(key);
  if (const MapLayout layout = map_layout(entry.variant.keys);
      layout != MapLayout::single && !scenes.placed.contains(layout)) {
    auto placed = prepare_placed(ctx.engine, scenes, layout);
    if (!placed) {
      target_runs.runs.push_back(
          {failed_run(target, ctx.backends.front()->name(), placed.error()), {}, {}, {}, {}});
      progress.finished(target_runs.label);
      return result;
    }
    scenes.placed.emplace(layout, std::move(*placed));
  }
  if (pair.minmax_preparer && !scenes.minmax) {
    scenes.minmax = prepare_minmax(ctx, ctx.library.variants[*pair.minmax_preparer], target,
                                   claim.reports_minmax ? result.checks : unreported);
  }
  for (const std::unique_ptr<Backend>& backend : ctx.backends) {
    if (!backend->executes(target) || !plan.runs_path(backend->name())) continue;
    target_runs.runs.push_back(run_on_device(ctx, *backend, entry, target, result.checks));
  }
  run_engine_forms(ctx, plan, entry, target, result.checks);
  target_runs.references = claim.references;
  const TargetScenes& read = variant_scenes(scenes, entry);
  target_runs.unchecked = read.scenes.size();
  for (std::size_t s = 0; s < read.scenes.size(); ++s) {
    work.submit(
        [&ctx, &runs = target_runs, &entry, target, s, &fixture = read.scenes[s], &progress] {
          check_scene_of_runs(runs, entry.variant, target, s, fixture,
                              placement_precision(fixture, ctx.precision));
          if (--runs.unchecked == 0) {
            runs.references.reset();
            progress.finished(runs.label);
          }
        });
  }
  return result;
}

// What every device thread shares.
struct Drive {
  const Library& library;
  const VerifyPlan& plan;
  const VerifyOptions& options;
  BytecodeTranslator bytecode;  // options.bytecode, its runs shared by every device thread
  reference::SamplingPrecision precision;
  SceneTruths truths{};
  PairQueue queue;
  CpuWork work;
  ProgressCounter progress;
  std::vector<std::vector<PairResult>> results;  // per planned variant and pair
  std::latch claimed;                            // every device thread has run its last pair
  std::latch checked;                            // every check has finished: the devices may close
  std::string gl_device{};
};

// One device thread: its own paths on `engine`, opened, driven and closed on
// this thread (an OpenGL context is current on one), running the pairs it
// claims until none is left. Its maps stay until every check has read them.
void drive_devices(Drive& drive, Engine& engine, std::size_t thread) {
  Context ctx{.library = drive.library,
              .engine = engine,
              .precision = drive.precision,
              .truths = drive.truths,
              .map_format = drive.options.map_format,
              .cameras = CameraStages(engine, drive.options.map_format)};
  // The paths, in report order: a new one is a new backend file and a row
  // in paths.cpp.
  ctx.backends = all_backends(engine, drive.bytecode, drive.options.skipped);
  for (const auto& backend : ctx.backends) {
    if (thread == 0 && backend->name() == "gl") drive.gl_device = backend->device();
  }
  // Every target this thread owns starts its slow devices now, while the
  // thread draws its first pairs.
  for (const Target target : drive.queue.own_targets(thread)) expect(ctx, drive.plan, target);
  drive.work.run([&] {
    while (const std::optional<PairQueue::Claim> claim = drive.queue.next(thread)) {
      drive.results[claim->variant][claim->pair] =
          run_pair(ctx, drive.plan, *claim, drive.work, drive.progress);
    }
  });
  drive.claimed.count_down();
  drive.checked.wait();
}

template <typename Check>
void append(std::vector<Check>& to, std::vector<Check>& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// A map's checks, in plan order. A path that draws its own maps checks each
// on the first run that draws it, on every device thread that draws it: the
// plan's first is the one a single thread makes, and the only one kept.
using DrawnMap = std::tuple<std::string, Target, std::string, MapEncoding, DepthFormat>;
void append_depth_checks(std::vector<DepthCheck>& to, std::vector<DepthCheck>& from,
                         std::set<DrawnMap>& drawn) {
  for (DepthCheck& check : from) {
    if (drawn
            .emplace(check.scene, check.target, check.backend, check.map_encoding, check.map_format)
            .second) {
      to.push_back(std::move(check));
    }
  }
}

void count(VerifyReport& report, const TargetRun& run) {
  if (!run.executed) return;
  if (!run.error.empty()) {
    ++report.runs;
    ++report.failed;
    return;
  }
  report.runs += run.scenes.size();
  for (const SceneRun& s : run.scenes) report.failed += s.pass() ? 0 : 1;
}

}  // namespace

bool SceneRun::pass() const {
  return comparison.pass && (!blur || blur->pass) && (!composite || composite->pass);
}

bool VerifyReport::pass() const {
  const bool depth_ok = std::all_of(depth_checks.begin(), depth_checks.end(),
                                    [](const DepthCheck& c) { return c.pass; });
  const bool minmax_ok = std::all_of(minmax_checks.begin(), minmax_checks.end(),
                                     [](const MinmaxCheck& c) { return c.pass; });
  const auto passed = [](const EngineFormCheck& c) { return c.pass; };
  const bool function_ok = std::all_of(function_checks.begin(), function_checks.end(), passed) &&
                           std::all_of(deferred_checks.begin(), deferred_checks.end(), passed);
  // Something must have run: a scene, or an engine form of a library built
  // without the query form.
  const bool ran = runs > 0 || !function_checks.empty() || !deferred_checks.empty();
  return depth_ok && minmax_ok && function_ok && failed == 0 && (ran || shard.count > 1);
}

Result<VerifyReport> verify_library(const Library& library, Engine& engine,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics) {
  Engine* const engines[] = {&engine};
  return verify_library(library, engines, options, diagnostics);
}

Result<VerifyReport> verify_library(const Library& library, std::span<Engine* const> engines,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics) {
  if (engines.empty()) return make_error(Error::Kind::internal, "verify", "no Vulkan device");
  PENUMBRA_TRY_ASSIGN(const VerifyPlan plan, plan_verify(library, options));
  const auto start = Clock::now();
  VerifyReport report;
  report.shard = options.shard;
  report.device = engines.front()->device_info();
  // With one CPU thread each job runs at once on the thread that submits
  // it, so one device thread drives every device then.
  const std::size_t threads = CpuWork::threads_for(options.jobs) == 1 ? 1 : engines.size();
  Drive drive{.library = library,
              .plan = plan,
              .options = options,
              .bytecode = shared_runs(options.bytecode),
              .precision = {static_cast<int>(std::max(1u, report.device.sub_texel_precision_bits))},
              .queue = PairQueue(plan, threads),
              .work = CpuWork(options.jobs, static_cast<int>(threads)),
              .progress = ProgressCounter(options.progress, plan.pair_count()),
              .results = {},
              .claimed = std::latch(static_cast<std::ptrdiff_t>(threads)),
              .checked = std::latch(1)};
  for (const PlannedVariant& v : plan.variants) drive.results.emplace_back(v.pairs.size());
  // The devices are driven from these threads, each with devices of its own;
  // the checks go to the CPU workers meanwhile, and are gathered in plan
  // order at the end.
  std::vector<std::jthread> device_threads;
  for (std::size_t t = 0; t < threads; ++t) {
    device_threads.emplace_back(
        [&drive, engine = engines[t], t] { drive_devices(drive, *engine, t); });
  }
  drive.claimed.wait();
  drive.work.wait();
  drive.checked.count_down();
  device_threads.clear();  // joined: every device closed
  report.gl_device = drive.gl_device;
  std::set<DrawnMap> drawn;
  for (std::size_t v = 0; v < plan.variants.size(); ++v) {
    const LibraryVariant& entry = library.variants[plan.variants[v].index];
    VariantRun variant_run;
    variant_run.name = entry.variant.name;
    variant_run.technique = entry.variant.technique;
    for (PairResult& pair : drive.results[v]) {
      finish_runs(*pair.runs, variant_run);
      append_depth_checks(report.depth_checks, pair.checks.depth_checks, drawn);
      append(report.minmax_checks, pair.checks.minmax_checks);
      append(report.function_checks, pair.checks.function_checks);
      append(report.deferred_checks, pair.checks.deferred_checks);
    }
    for (const TargetRun& run : variant_run.runs) count(report, run);
    if (plan.variants[v].other_shards && variant_run.runs.empty()) continue;
    diagnostics({Severity::note, entry.variant.name, "verified"});
    report.variants.push_back(std::move(variant_run));
  }
  // The per-target checks of the pairs another shard runs are that shard's.
  std::erase_if(report.depth_checks, [&](const DepthCheck& c) {
    return !plan.reports_depth({c.target, c.map_encoding});
  });
  std::erase_if(report.minmax_checks, [&](const MinmaxCheck& c) {
    return !plan.reports_minmax({c.target, c.map_encoding});
  });
  report.seconds = seconds_since(start);
  return report;
}

}  // namespace penumbra
