#include <algorithm>
#include <map>

#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/runtime/verify.hpp"
#include "verify/chain_check.hpp"
#include "verify/gl_backend.hpp"
#include "verify/minmax_check.hpp"
#include "verify/scene_fixture.hpp"

namespace penumbra {
namespace {

// A target's scenes, each rendered by that target's own depth pass.
struct TargetFixtures {
  Execution depth_execution;
  std::vector<SceneFixture> scenes;
};

struct Context {
  const Library& library;
  Engine& engine;
  reference::SamplingPrecision precision;
  std::map<Target, TargetFixtures> fixtures;
  std::unique_ptr<GlBackend> gl;
  std::string gl_missing;  // why there is no GL path
  // Targets whose depth pass could not run: every run on them fails with this.
  std::map<Target, Error> broken_targets;
  // Targets whose scenes' maps hold the min-max mip their own passes built,
  // or why it could not be built: every run on them that reads it fails then.
  std::map<Target, Status> minmax_built;
};

// A run that could not compile or execute its shaders is a failed check of
// that variant and target, not a reason to stop verifying the others.
TargetRun failed_run(Target target, std::string backend, const Error& error) {
  TargetRun run;
  run.target = target;
  run.backend = std::move(backend);
  run.executed = true;
  run.error = error.to_string();
  return run;
}

// The query's visibility against the reference (screen_blur: the factor).
Result<SceneRun> check_scene(const Context& ctx, const FloatImage& visibility,
                             const FloatImage& texel_reads, const Variant& variant,
                             const SceneFixture& fixture) {
  auto expected = reference::evaluate_image(variant, fixture.linear_depth, fixture.scene.light,
                                            fixture.receivers, ctx.precision);
  if (!expected) return expected.error();
  auto comparison = reference::compare(visibility, expected->visibility, expected->ambiguous,
                                       reference::tolerance(variant.technique, ctx.precision));
  if (!comparison) return comparison.error();
  double reads = 0.0;
  for (float r : texel_reads.data) reads += r;
  return SceneRun{fixture.scene.name, *comparison,
                  reads / static_cast<double>(texel_reads.pixel_count()), std::nullopt,
                  std::nullopt};
}

Result<SceneRun> check_query_scene(const Context& ctx, Result<QueryOutput> gpu,
                                   const Variant& variant, const SceneFixture& fixture) {
  if (!gpu) return gpu.error();
  return check_scene(ctx, gpu->visibility, gpu->texel_reads, variant, fixture);
}

// screen_blur's chain checked step by step, so that one ambiguous point
// compare in the factor does not spread through the blur: the factor against
// the reference, then each later pass against the CPU's step applied to the
// GPU's own input to it.
Result<SceneRun> check_screen_blur_scene(const Context& ctx, const ScreenBlurOutput& gpu,
                                         const Variant& variant, const SceneFixture& fixture,
                                         const FloatImage& colour) {
  auto scene = check_scene(ctx, gpu.factor, gpu.texel_reads, variant, fixture);
  if (!scene) return scene.error();
  auto blur =
      check_chain(gpu.blurred, reference::screen_blur(variant, gpu.factor, fixture.receivers),
                  reference::kBlurTolerance, "the blurred factor");
  if (!blur) return blur.error();
  auto composite = check_chain(gpu.composite, reference::composite(colour, gpu.blurred),
                               reference::kCompositeTolerance, "the composite");
  if (!composite) return composite.error();
  scene->blur = *blur;
  scene->composite = *composite;
  return scene;
}

// Runs `check` (a scene run and its checks) on every scene of the target's
// fixtures.
template <typename Check>
Status run_scenes(Context& ctx, TargetRun& run, Check check) {
  run.executed = true;
  run.pass = true;
  for (const SceneFixture& fixture : ctx.fixtures.at(run.target).scenes) {
    Result<SceneRun> scene = check(fixture);
    if (!scene) return scene.error();
    run.pass = run.pass && scene->pass();
    run.scenes.push_back(std::move(*scene));
  }
  return {};
}

// The chain's four passes of `target` on every scene.
Status run_screen_blur_scenes(Context& ctx, const LibraryVariant& entry, TargetRun& run) {
  auto programs = load_screen_blur(ctx.library, entry, run.target);
  if (!programs) return programs.error();
  run.execution = programs->query.execution;
  return run_scenes(ctx, run, [&](const SceneFixture& fixture) -> Result<SceneRun> {
    const FloatImage colour =
        reference::scene_colour(fixture.receivers.width, fixture.receivers.height);
    auto gpu = ctx.engine.run_screen_blur(programs->programs(), *fixture.map, fixture.receivers,
                                          colour, fixture.params);
    if (!gpu) return gpu.error();
    return check_screen_blur_scene(ctx, *gpu, entry.variant, fixture, colour);
  });
}

Result<TargetRun> run_vulkan(Context& ctx, const LibraryVariant& entry, Target target) {
  TargetRun run;
  run.target = target;
  run.device = ctx.engine.device_info().name;
  if (entry.variant.technique == Technique::screen_blur) {
    PENUMBRA_TRY(run_screen_blur_scenes(ctx, entry, run));
    return run;
  }
  auto query = load_executable(ctx.library, entry, PassKind::query, target);
  if (!query) return query.error();
  run.execution = query->execution;
  PENUMBRA_TRY(run_scenes(ctx, run, [&](const SceneFixture& fixture) {
    return check_query_scene(ctx,
                             ctx.engine.run_query_output(query->program, *fixture.map,
                                                         fixture.receivers, fixture.params),
                             entry.variant, fixture);
  }));
  return run;
}

// run_vulkan, or a failed run when the mip the variant reads could not be built.
TargetRun vulkan_run(Context& ctx, const LibraryVariant& entry, Target target) {
  if (uses_minmax_mip(entry.variant.technique)) {
    if (const Status& built = ctx.minmax_built.at(target); !built) {
      return failed_run(target, "vulkan", built.error());
    }
  }
  auto run = run_vulkan(ctx, entry, target);
  return run ? std::move(*run) : failed_run(target, "vulkan", run.error());
}

// The same text through the OpenGL driver, bound by its reflection, on the
// map the target's own depth pass rendered (the GL engine builds the min-max
// mip with the target's own passes when the query reads it); screen_blur's
// chain checked as on Vulkan.
Result<TargetRun> run_gl(Context& ctx, const LibraryVariant& entry, Target target) {
  TargetRun run;
  run.target = target;
  run.backend = "gl";
  if (!ctx.gl) {
    run.not_executed = ctx.gl_missing;
    return run;
  }
  run.device = ctx.gl->device();
  run.execution.front_end = "the OpenGL driver's GLSL compiler";
  if (entry.variant.technique == Technique::screen_blur) {
    auto chain = read_gl_screen_blur(ctx.library, entry, target);
    if (!chain) return chain.error();
    PENUMBRA_TRY(run_scenes(ctx, run, [&](const SceneFixture& fixture) -> Result<SceneRun> {
      const FloatImage colour =
          reference::scene_colour(fixture.receivers.width, fixture.receivers.height);
      auto gpu = ctx.gl->run_screen_blur(*chain, fixture.normalized_depth, fixture.receivers,
                                         colour, fixture.params);
      if (!gpu) return gpu.error();
      return check_screen_blur_scene(ctx, *gpu, entry.variant, fixture, colour);
    }));
    return run;
  }
  auto texts = read_gl_query(ctx.library, entry, target);
  if (!texts) return texts.error();
  PENUMBRA_TRY(run_scenes(ctx, run, [&](const SceneFixture& fixture) {
    return check_query_scene(
        ctx, ctx.gl->run_query(*texts, fixture.normalized_depth, fixture.receivers, fixture.params),
        entry.variant, fixture);
  }));
  return run;
}

// Renders every scene with `target`'s depth pass (shared by all variants),
// taken from `entry`, a variant that has the target.
Status prepare_target(Context& ctx, const LibraryVariant& entry, Target target,
                      VerifyReport& report) {
  auto depth = load_executable(ctx.library, entry, PassKind::depth, target);
  if (!depth) return depth.error();
  TargetFixtures fixtures{depth->execution, {}};
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    auto fixture = prepare_scene(ctx.engine, depth->program, target, scene);
    if (!fixture) return fixture.error();
    report.depth_checks.push_back(fixture->depth_check);
    fixtures.scenes.push_back(std::move(*fixture));
  }
  ctx.fixtures.emplace(target, std::move(fixtures));
  return {};
}

// Builds the min-max mip on every scene's map of `target` with the target's
// own minmax passes (shared by all variants), taken from `entry`, a variant
// that has them, and checks each against the CPU mip.
Status prepare_minmax(Context& ctx, const LibraryVariant& entry, Target target,
                      VerifyReport& report) {
  auto init = load_executable(ctx.library, entry, PassKind::minmax_init, target);
  if (!init) return init.error();
  auto reduce = load_executable(ctx.library, entry, PassKind::minmax_reduce, target);
  if (!reduce) return reduce.error();
  for (SceneFixture& fixture : ctx.fixtures.at(target).scenes) {
    auto built =
        ctx.engine.build_minmax(*fixture.map, init->program, reduce->program, fixture.params);
    auto levels = built ? ctx.engine.read_minmax(*fixture.map)
                        : Result<std::vector<FloatImage>>(built.error());
    if (!levels) {
      MinmaxCheck failed;
      failed.scene = fixture.scene.name;
      failed.target = target;
      failed.error = levels.error().to_string();
      report.minmax_checks.push_back(std::move(failed));
      return levels.error();
    }
    report.minmax_checks.push_back(check_minmax(fixture, target, *levels));
  }
  return {};
}

bool wanted(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
}

bool wanted(const std::vector<Target>& targets, Target target) {
  return targets.empty() || std::find(targets.begin(), targets.end(), target) != targets.end();
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
  return depth_ok && minmax_ok && failed == 0 && runs > 0;
}

Result<VerifyReport> verify_library(const Library& library, Engine& engine,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics) {
  if (library.variants.empty()) {
    return make_error(Error::Kind::bad_input, library.root.string(), "the library has no variants");
  }
  for (const std::string& name : options.variants) {
    if (!library.find(name)) {
      return make_error(Error::Kind::bad_input, name,
                        "no such variant in " + library.root.string());
    }
  }
  VerifyReport report;
  report.device = engine.device_info();
  Context ctx{
      library, engine,  {static_cast<int>(std::max(1u, report.device.sub_texel_precision_bits))},
      {},      nullptr, {},
      {},      {}};
  if (options.gl) {
    const bool lavapipe = report.device.name.find("llvmpipe") != std::string::npos;
    ctx.gl = GlBackend::create(lavapipe ? "llvmpipe" : "", ctx.gl_missing);
    if (ctx.gl) report.gl_device = ctx.gl->device();
  } else {
    ctx.gl_missing = "not requested (--no-gl)";
  }

  for (const LibraryVariant& entry : library.variants) {
    if (!wanted(options.variants, entry.variant.name)) continue;
    VariantRun variant_run;
    variant_run.name = entry.variant.name;
    variant_run.technique = entry.variant.technique;
    for (Target target : entry.variant.targets) {
      if (!wanted(options.targets, target)) continue;
      if (!ctx.fixtures.contains(target) && !ctx.broken_targets.contains(target)) {
        // A depth pass that cannot run fails every run of its target, not verify.
        if (Status s = prepare_target(ctx, entry, target, report); !s) {
          ctx.broken_targets.emplace(target, s.error());
        }
      }
      if (auto broken = ctx.broken_targets.find(target); broken != ctx.broken_targets.end()) {
        variant_run.runs.push_back(failed_run(target, "vulkan", broken->second));
        count(report, variant_run.runs.back());
        continue;
      }
      if (uses_minmax_mip(entry.variant.technique) && !ctx.minmax_built.contains(target)) {
        ctx.minmax_built.emplace(target, prepare_minmax(ctx, entry, target, report));
      }
      variant_run.runs.push_back(vulkan_run(ctx, entry, target));
      count(report, variant_run.runs.back());
      if (target == Target::glsl330 || target == Target::glsl450) {
        auto gl_run = run_gl(ctx, entry, target);
        variant_run.runs.push_back(gl_run ? std::move(*gl_run)
                                          : failed_run(target, "gl", gl_run.error()));
        count(report, variant_run.runs.back());
      }
    }
    diagnostics({Severity::note, entry.variant.name, "verified"});
    report.variants.push_back(std::move(variant_run));
  }
  return report;
}

}  // namespace penumbra
