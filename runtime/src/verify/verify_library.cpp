#include <algorithm>

#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/runtime/verify.hpp"
#include "verify/scene_fixture.hpp"

namespace penumbra {
namespace {

// How each target is executed. Only SPIR-V runs for now; the text targets
// are validated at build time and report why they were not executed.
bool executable(Target target) {
  return target == Target::spirv;
}

std::string not_executed_reason(Target target) {
  return "not executed: running " + std::string(to_string(target)) +
         " text on the device is not implemented yet; validated at build time";
}

Result<SceneRun> run_scene(Engine& engine, const PassProgram& query, const Variant& variant,
                           const SceneFixture& fixture,
                           const reference::SamplingPrecision& precision) {
  auto gpu = engine.run_query(query, *fixture.map, fixture.receivers, fixture.params);
  if (!gpu) return gpu.error();
  auto expected = reference::evaluate_image(variant, fixture.linear_depth, fixture.scene.light,
                                            fixture.receivers, precision);
  if (!expected) return expected.error();
  auto comparison = reference::compare(*gpu, expected->visibility, expected->ambiguous,
                                       reference::tolerance(variant.technique, precision));
  if (!comparison) return comparison.error();
  return SceneRun{fixture.scene.name, *comparison};
}

Result<TargetRun> run_target(Engine& engine, const Library& library, const LibraryVariant& entry,
                             Target target, const std::vector<SceneFixture>& fixtures,
                             const reference::SamplingPrecision& precision) {
  TargetRun run;
  run.target = target;
  if (!executable(target)) {
    run.how = not_executed_reason(target);
    return run;
  }
  auto query = load_program(library, entry, PassKind::query, target);
  if (!query) return query.error();
  run.executed = true;
  run.how = "SPIR-V as built, on " + engine.device_info().name;
  run.pass = true;
  for (const SceneFixture& fixture : fixtures) {
    auto scene = run_scene(engine, *query, entry.variant, fixture, precision);
    if (!scene) return scene.error();
    run.pass = run.pass && scene->comparison.pass;
    run.scenes.push_back(std::move(*scene));
  }
  return run;
}

bool selected(const VerifyOptions& options, const std::string& name) {
  return options.variants.empty() || std::find(options.variants.begin(), options.variants.end(),
                                               name) != options.variants.end();
}

}  // namespace

bool VerifyReport::pass() const {
  const bool depth_ok = std::all_of(depth_checks.begin(), depth_checks.end(),
                                    [](const DepthCheck& c) { return c.pass; });
  return depth_ok && failed == 0 && runs > 0;
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
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, report.device.sub_texel_precision_bits))};

  // The depth pass is shared by every variant: render each scene once.
  auto depth = load_program(library, library.variants.front(), PassKind::depth, Target::spirv);
  if (!depth) return depth.error();
  std::vector<SceneFixture> fixtures;
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    auto fixture = prepare_scene(engine, *depth, scene);
    if (!fixture) return fixture.error();
    report.depth_checks.push_back(fixture->depth_check);
    fixtures.push_back(std::move(*fixture));
  }

  for (const LibraryVariant& entry : library.variants) {
    if (!selected(options, entry.variant.name)) continue;
    VariantRun variant_run;
    variant_run.name = entry.variant.name;
    variant_run.technique = entry.variant.technique;
    for (Target target : entry.variant.targets) {
      auto run = run_target(engine, library, entry, target, fixtures, precision);
      if (!run) return run.error();
      if (run->executed) {
        report.runs += run->scenes.size();
        for (const SceneRun& s : run->scenes) report.failed += s.comparison.pass ? 0 : 1;
      }
      variant_run.targets.push_back(std::move(*run));
    }
    diagnostics({Severity::note, entry.variant.name, "verified"});
    report.variants.push_back(std::move(variant_run));
  }
  return report;
}

}  // namespace penumbra
