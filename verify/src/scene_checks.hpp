// The CPU's part of verify: what every path's passes wrote for one
// (variant, target), checked against the CPU reference scene by scene on a
// CPU worker (cpu_work.hpp) while the device thread runs the next target.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

#include "backend.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/verify/verify.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start);

// A run that could not compile or execute its shaders is a failed check of
// that variant and target, not a reason to stop verifying the others.
TargetRun failed_run(Target target, std::string backend, const Error& error);

// One path's run of a (variant, target): its passes ran on the device
// (`outputs`, one per scene); check_scene_of_runs() fills `checked`.
struct PendingRun {
  TargetRun run;
  std::vector<SceneOutput> outputs;
  std::vector<Result<SceneRun>> checked;
  std::vector<double> device_seconds;  // per scene
  std::vector<double> check_seconds;   // per scene
};

// One variant's references, shared by the checks of all its targets and
// paths: each computed once per distinct input (the scene, the target's
// shader limits, the map's encoding and its content, byte for byte), by
// whichever check asks first. The targets' maps are mostly the same
// texels, so a variant's seven targets and Wine's own maps need only a few.
struct VariantReferences;
std::shared_ptr<VariantReferences> variant_references();

// Every path's run of one (variant, target).
struct PendingTarget {
  std::vector<PendingRun> runs;
  std::atomic<std::size_t> unchecked{0};  // scenes whose checks have not finished
  std::string label;                      // "variant [target]", for the progress
  // Its variant's, until its last check has finished (then the references
  // are freed once every target of the variant is done).
  std::shared_ptr<VariantReferences> references;
};

// Scene `s` (`fixture`) of every run in `target_runs` against the
// reference of `target`'s shader on the map the run read (the fixture's,
// or a path's own), from `target_runs.references`. Reads no map the device
// thread may change.
void check_scene_of_runs(PendingTarget& target_runs, const Variant& variant, Target target,
                         std::size_t s, const SceneFixture& fixture,
                         const reference::SamplingPrecision& precision);

// Each run with its checked scenes, in order, appended to `variant_run`: a
// scene whose check erred fails its run, as one the device could not run.
void finish_runs(PendingTarget& target_runs, VariantRun& variant_run);

}  // namespace penumbra
