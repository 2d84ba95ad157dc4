#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <string_view>
#include <thread>
#include <tuple>

#include "build/index_json.hpp"
#include "build/pass_plan.hpp"
#include "build/pipeline.hpp"
#include "build/streamed_index.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/library/disk_json.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/content_hash.hpp"
#include "reflect/reflect_target.hpp"
#include "stages/stages.hpp"

namespace penumbra {
namespace {

// Shared shaders once per target and map encoding, when a variant for that
// target and encoding uses their pass; then each variant's own.
std::vector<ShaderJob> plan_jobs(std::span<const Variant> variants) {
  std::vector<ShaderJob> jobs;
  for (Target target : kAllTargets) {
    for (const PassStageSource& source : pass_plan()) {
      if (source.per_variant) continue;
      for (const MapEncoding encoding : kAllMapEncodings) {
        const auto user = std::ranges::find_if(variants, [&](const Variant& v) {
          return std::ranges::find(v.targets, target) != v.targets.end() &&
                 runs_pass(source.pass, v) && job_encoding(source, v) == encoding;
        });
        if (user != variants.end()) jobs.push_back(make_job(source, target, *user));
      }
    }
  }
  for (const Variant& variant : variants) {
    for (Target target : variant.targets) {
      for (const PassStageSource& source : pass_plan()) {
        if (source.per_variant && runs_pass(source.pass, variant)) {
          jobs.push_back(make_job(source, target, variant));
        }
      }
      if (builds_form(variant, Form::function) && traits(target).is_text) {
        jobs.push_back(make_function_job(target, variant));
      }
    }
  }
  return jobs;
}

// The jobs in groups a worker runs one after another: those of one
// variant's shader source for each of its targets, which share their module
// where the targets' texts agree (the module memo), so that no two workers
// make the same module at once. Groups and the jobs in each keep plan order.
std::vector<std::vector<std::size_t>> module_groups(const std::vector<ShaderJob>& jobs) {
  using Source = std::tuple<const Variant*, std::string_view, ShaderStage, ShaderForm>;
  std::map<Source, std::size_t> group_of;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const ShaderJob& job = jobs[i];
    const Source source{job.variant, job.source_path, job.stage, job.form};
    const auto [found, added] = group_of.try_emplace(source, groups.size());
    if (added) groups.emplace_back();
    groups[found->second].push_back(i);
  }
  return groups;
}

// Runs all jobs on `threads` workers, a group at a time; unless
// `keep_going`, stops early after a failure. A finished job keeps only what
// index.json needs until `index` has its variant's record. The errors of
// the failed jobs, in plan order.
std::vector<Error> run_jobs(std::vector<ShaderJob>& jobs, const Pipeline& pipeline,
                            StreamedIndex& index, const BuildOptions& options, int threads) {
  const std::vector<std::vector<std::size_t>> groups = module_groups(jobs);
  std::vector<std::optional<Error>> errors(jobs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex progress_mutex;
  std::size_t finished = 0;
  auto run = [&](std::size_t i) {
    try {
      if (Status status = pipeline.run(jobs[i]); !status) errors[i] = status.error();
    } catch (const std::exception& e) {  // a library below us threw: report, never terminate
      errors[i] = make_error(Error::Kind::internal, jobs[i].describe(), e.what());
    }
    jobs[i].release_code();
    if (errors[i]) {
      failed = true;
    } else {
      index.finished(i);
    }
    if (options.progress) {
      const std::scoped_lock lock(progress_mutex);
      options.progress(++finished, jobs.size());
    }
  };
  auto worker = [&] {
    for (std::size_t g = next++; g < groups.size(); g = next++) {
      for (std::size_t i : groups[g]) {
        if (!options.keep_going && failed) return;
        run(i);
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
  }
  std::vector<Error> failures;
  for (auto& error : errors) {
    if (error) failures.push_back(std::move(*error));
  }
  return failures;
}

// A pass the variant's technique does not run is bad input.
Status check_runs_pass(const Variant& variant, PassKind pass) {
  if (runs_pass(pass, variant)) return {};
  return make_error(Error::Kind::bad_input, "variant " + variant.name,
                    "has no " + std::string(to_string(pass)) + " pass (technique " +
                        std::string(to_string(variant.technique)) + " does not use it)");
}

// --keep-going's summary: how many shaders failed, of how many.
Error keep_going_error(const std::vector<Error>& failures, std::size_t jobs,
                       const std::filesystem::path& out) {
  return make_error(failures.front().kind, out.string(),
                    std::to_string(failures.size()) + " of " + std::to_string(jobs) +
                        " shaders failed (each reported above); not written, left as it was");
}

}  // namespace

std::string_view penumbra_version() {
  return PENUMBRA_VERSION;
}

std::string toolchain_id() {
  static const std::string id = [] {
    std::string out = "penumbra " + std::string(penumbra_version());
    if (const std::string build = executable_build_id(); !build.empty()) out += "; build " + build;
    out += "; glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." +
           std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH);
    out += "; " + std::string(spvSoftwareVersionDetailsString());
    return out;
  }();
  return id;
}

std::string variant_identity(const Variant& variant) {
  nlohmann::json out = {{"name", variant.name},
                        {"technique", to_string(variant.technique)},
                        {"keys", variant_keys_json(variant.keys)}};
  if (variant.blocker_disk) out["blocker_disk"] = disk_to_json(*variant.blocker_disk);
  if (variant.pcf_disk) out["pcf_disk"] = disk_to_json(*variant.pcf_disk);
  out["blur_weights"] = variant.blur_weights;
  return out.dump();
}

Result<BuildSummary> build_library(std::span<const Variant> variants,
                                   const std::filesystem::path& out_dir,
                                   const BuildOptions& options,
                                   const DiagnosticConsumer& diagnostics) {
  PENUMBRA_TRY(check_output_directory(out_dir));
  const auto shaderlib = options.shaderlib ? options.shaderlib : embedded_shaderlib();
  auto staged = StagedDirectory::create(out_dir);
  if (!staged) return staged.error();

  std::vector<ShaderJob> jobs = plan_jobs(variants);
  // No more threads than shaders.
  const int threads =
      std::clamp(options.jobs, 1, static_cast<int>(std::max<std::size_t>(jobs.size(), 1)));
  diagnostics({Severity::note, out_dir.string(),
               "compiling " + std::to_string(jobs.size()) + " shaders for " +
                   std::to_string(variants.size()) + " variants on " + std::to_string(threads) +
                   " threads"});
  const Pipeline pipeline(shaderlib, staged->staging(), options.hlsl, options.cache_dir);
  StreamedIndex index(variants, jobs);
  std::vector<Error> failures = run_jobs(jobs, pipeline, index, options, threads);
  if (!failures.empty() && !options.keep_going) return failures.front();
  for (const ShaderJob& job : jobs) {
    for (const Diagnostic& d : job.diagnostics) diagnostics(d);
  }
  if (!failures.empty()) {
    for (const Error& e : failures) diagnostics({Severity::error, e.where, e.message});
    return keep_going_error(failures, jobs.size(), out_dir);
  }

  PENUMBRA_TRY(write_file_atomic(staged->staging() / "index.json", index.finish()));
  // Unchanged output keeps its times: a build system then reruns nothing
  // that depends on it.
  PENUMBRA_TRY(staged->commit_if_changed());
  if (!staged->leftover().empty()) {
    diagnostics({Severity::warning, out_dir.string(),
                 "replaced, but the previous library could not be removed from " +
                     staged->leftover().string() + "; the next build into it tries again"});
  }
  std::set<std::string> inputs;
  for (const std::string& path : index.inputs()) inputs.insert(shaderlib->location(path));
  std::vector<StageTime> profile = pipeline.profile();
  profile.push_back({"index", index.seconds(), index.written()});
  return BuildSummary{.variants = variants.size(),
                      .files = jobs.size(),
                      .bytecode = index.bytecode(),
                      .cached = index.cached(),
                      .inputs = {inputs.begin(), inputs.end()},
                      .profile = std::move(profile)};
}

Result<CompiledPass> compile_pass(const Variant& variant, Target target, PassKind pass,
                                  std::shared_ptr<const ShaderlibSource> shaderlib) {
  PENUMBRA_TRY(check_runs_pass(variant, pass));
  const Pipeline pipeline(shaderlib ? std::move(shaderlib) : embedded_shaderlib(), std::nullopt);
  CompiledPass out;
  PassReflection vert;
  PassReflection frag;
  for (const PassStageSource& source : pass_plan()) {
    if (source.pass != pass) continue;
    ShaderJob job = make_job(source, target, variant);
    PENUMBRA_TRY(pipeline.run(job));
    const bool is_vertex = source.stage == ShaderStage::vertex;
    (is_vertex ? vert : frag) = std::move(job.reflection);
    CompiledStage& stage = is_vertex ? out.vert : out.frag;
    stage = CompiledStage{std::move(job.spirv), std::move(job.text), std::move(job.interface)};
  }
  out.reflection = join_stages(std::move(vert), frag);
  return out;
}

namespace {

// A function form that cannot be made is bad input.
Status check_function_form(const Variant& variant, Target target) {
  if (!has_function_form(variant.technique)) {
    return make_error(Error::Kind::bad_input, "variant " + variant.name,
                      "has no function form (technique " +
                          std::string(to_string(variant.technique)) +
                          " has none: docs/function-form.md); allowed: every technique but "
                          "screen_blur");
  }
  if (!traits(target).is_text) {
    return make_error(Error::Kind::bad_input, "target " + std::string(to_string(target)),
                      "has no function form: it is not text (a Vulkan engine includes the "
                      "glsl450 one)");
  }
  return {};
}

// `job`'s preprocessed text.
Result<std::string> preprocessed(ShaderJob job, std::shared_ptr<const ShaderlibSource> shaderlib) {
  const PreprocessStage preprocess(shaderlib ? std::move(shaderlib) : embedded_shaderlib());
  if (Status status = preprocess.process(job); !status) {
    Error error = status.error();
    error.message = "preprocess: " + error.message;
    return error;
  }
  return std::move(job.preprocessed);
}

}  // namespace

Result<CompiledFunction> compile_function(const Variant& variant, Target target,
                                          std::shared_ptr<const ShaderlibSource> shaderlib) {
  PENUMBRA_TRY(check_function_form(variant, target));
  const Pipeline pipeline(shaderlib ? std::move(shaderlib) : embedded_shaderlib(), std::nullopt);
  ShaderJob job = make_function_job(target, variant);
  PENUMBRA_TRY(pipeline.run(job));
  return CompiledFunction{std::move(job.text), std::move(job.reflection)};
}

Result<std::string> preprocess_shader(const Variant& variant, Target target, PassKind pass,
                                      ShaderStage stage,
                                      std::shared_ptr<const ShaderlibSource> shaderlib) {
  PENUMBRA_TRY(check_runs_pass(variant, pass));
  const auto source = std::ranges::find_if(
      pass_plan(), [&](const PassStageSource& s) { return s.pass == pass && s.stage == stage; });
  // pass_plan() lists both stages of every pass.
  return preprocessed(make_job(*source, target, variant), std::move(shaderlib));
}

Result<std::string> preprocess_function(const Variant& variant, Target target,
                                        std::shared_ptr<const ShaderlibSource> shaderlib) {
  PENUMBRA_TRY(check_function_form(variant, target));
  return preprocessed(make_function_job(target, variant), std::move(shaderlib));
}

}  // namespace penumbra
