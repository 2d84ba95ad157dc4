#include "scene_checks.hpp"

#include <string_view>

#include "chain_check.hpp"
#include "memo.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra {
namespace {

// The query's visibility against `expected` (screen_blur: the factor).
Result<SceneRun> check_scene(const SceneOutput& gpu, const reference::ReferenceImage& expected,
                             const Variant& variant, const SceneFixture& fixture,
                             const reference::SamplingPrecision& precision) {
  PENUMBRA_TRY_ASSIGN(auto comparison,
                      reference::compare(gpu.visibility, expected.visibility, expected.ambiguous,
                                         reference::tolerance(variant.technique, precision)));
  double reads = 0.0;
  for (float r : gpu.texel_reads.data) reads += r;
  SceneRun scene{fixture.scene.name, comparison,
                 reads / static_cast<double>(gpu.texel_reads.pixel_count()), std::nullopt,
                 std::nullopt};
  if (!gpu.chain) return scene;
  // screen_blur's chain checked step by step, so that one ambiguous point
  // compare in the factor does not spread through the blur: each later pass
  // against the CPU's step applied to the GPU's own input to it.
  const ChainOutput& chain = *gpu.chain;
  PENUMBRA_TRY_ASSIGN(
      scene.blur,
      check_chain(chain.blurred, reference::screen_blur(variant, gpu.visibility, fixture.receivers),
                  reference::kBlurTolerance, "the blurred factor"));
  PENUMBRA_TRY_ASSIGN(
      scene.composite,
      check_chain(chain.composite, reference::composite(fixture.colour, chain.blurred),
                  reference::kCompositeTolerance, "the composite"));
  return scene;
}

// An image in a key: equal when its values are, byte for byte (a NaN
// equals itself, -0 does not equal 0), with a hash to tell most apart fast.
struct ImageKey {
  explicit ImageKey(const FloatImage& i)
      : image(&i),
        hash(std::hash<std::string_view>{}(
            {reinterpret_cast<const char*>(i.data.data()), i.data.size() * sizeof(float)})) {}
  bool operator==(const ImageKey& o) const {
    return hash == o.hash && same_bytes(*image, *o.image);
  }
  const FloatImage* image;  // outlives the key: the fixture's, or a run's output
  std::size_t hash;
};

// What reference_on_map() reads beside the variant and the precision.
struct ReferenceKey {
  reference::Scene scene;  // its light
  reference::ShaderLimits limits;
  std::optional<reference::EncodedDepth> encoded;
  ImageKey map;  // as the reference reads it: as stored where encoded, else linear z
  ImageKey receivers;
  bool operator==(const ReferenceKey&) const = default;
};

}  // namespace

// Opaque to the header, whose users only share and free it.
struct VariantReferences {
  Memo<ReferenceKey, Result<reference::ReferenceImage>> memo;
};

std::shared_ptr<VariantReferences> variant_references() {
  return std::make_shared<VariantReferences>();
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

TargetRun failed_run(Target target, std::string backend, const Error& error) {
  TargetRun run;
  run.target = target;
  run.backend = std::move(backend);
  run.executed = true;
  run.error = error.to_string();
  return run;
}

void check_scene_of_runs(PendingTarget& target_runs, const Variant& variant, Target target,
                         std::size_t s, const SceneFixture& fixture,
                         const reference::SamplingPrecision& precision) {
  const reference::ShaderLimits limits = reference::shader_limits(target);
  const auto reference_on = [&](const FloatImage& stored, const FloatImage& linear) -> const auto& {
    const ReferenceKey key{fixture.scene, limits, fixture.encoded,
                           ImageKey(fixture.encoded ? stored : linear),
                           ImageKey(fixture.receivers)};
    return target_runs.references->memo.get(
        key, [&] { return reference_on_map(variant, fixture, stored, linear, precision, limits); });
  };
  for (PendingRun& pending : target_runs.runs) {
    if (pending.outputs.empty()) continue;
    const auto start = Clock::now();
    const SceneOutput& gpu = pending.outputs[s];
    const Result<reference::ReferenceImage>& expected =
        gpu.own_linear_depth ? reference_on(*gpu.own_stored_depth, *gpu.own_linear_depth)
                             : reference_on(fixture.normalized_depth, fixture.linear_depth);
    pending.checked[s] = expected ? check_scene(gpu, *expected, variant, fixture, precision)
                                  : Result<SceneRun>(expected.error());
    pending.check_seconds[s] = seconds_since(start);
    if (pending.checked[s]) {
      pending.checked[s]->seconds = pending.device_seconds[s] + pending.check_seconds[s];
    }
  }
}

void finish_runs(PendingTarget& target_runs, VariantRun& variant_run) {
  for (PendingRun& pending : target_runs.runs) {
    TargetRun& run = pending.run;
    if (!pending.outputs.empty()) run.pass = true;
    for (std::size_t s = 0; s < pending.checked.size(); ++s) {
      Result<SceneRun>& scene = pending.checked[s];
      run.seconds += pending.check_seconds[s];
      if (!scene) {
        const double seconds = run.seconds;
        run = failed_run(run.target, run.backend, scene.error());
        run.seconds = seconds;
        break;
      }
      run.pass = run.pass && scene->pass();
      run.scenes.push_back(std::move(*scene));
    }
    variant_run.runs.push_back(std::move(run));
  }
}

}  // namespace penumbra
