#include "build/pipeline.hpp"

#include <chrono>

#include "build/module_memo.hpp"
#include "cache/shader_cache.hpp"
#include "stages/stages.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra {
namespace {

// stages_[1, 1 + kModuleStages): compile, validate, optimize, interface.
constexpr std::size_t kModuleStages = 4;
// Modules remembered for the jobs after: one variant's targets follow each
// other in plan order, a few jobs apart.
constexpr std::size_t kRememberedModules = 64;

Status run_stage(const Stage& stage, ShaderJob& job) {
  Status status = stage.process(job);
  if (!status) {
    Error error = status.error();
    error.message = std::string(stage.name()) + ": " + error.message;
    return error;
  }
  return {};
}

// The tools a cached file came from: the linked compilers, and the HLSL
// compiler's own version line when the build makes bytecode.
std::string cache_toolchain(const HlslCompilerOptions& hlsl) {
  std::string out = toolchain_id();
  if (hlsl.compiler.empty()) return out;
  auto version = run_vkd3d(hlsl.compiler, {"--version"}, hlsl.timeout);
  out +=
      "; hlsl " + (version && version->exit_code == 0 ? version->output : hlsl.compiler.string());
  return out;
}

}  // namespace

Pipeline::Pipeline(std::shared_ptr<const ShaderlibSource> shaderlib,
                   std::optional<std::filesystem::path> write_root, const HlslCompilerOptions& hlsl,
                   const std::filesystem::path& cache_dir)
    : write_root_(std::move(write_root)) {
  stages_.push_back(std::make_unique<PreprocessStage>(shaderlib));
  stages_.push_back(std::make_unique<CompileStage>(std::move(shaderlib)));
  stages_.push_back(std::make_unique<ValidateStage>());
  stages_.push_back(std::make_unique<OptimizeStage>());
  stages_.push_back(std::make_unique<InterfaceStage>());
  stages_.push_back(std::make_unique<BannerStage>());
  stages_.push_back(std::make_unique<CrossCompileStage>());
  stages_.push_back(std::make_unique<ReflectStage>());
  stages_.push_back(std::make_unique<ExtractFunctionStage>());
  if (write_root_) {
    stages_.push_back(std::make_unique<WriteStage>(*write_root_));
    if (!hlsl.compiler.empty()) {
      stages_.push_back(std::make_unique<BytecodeStage>(*write_root_, hlsl));
    }
    if (!cache_dir.empty()) {
      cache_ = std::make_unique<ShaderCache>(cache_dir, cache_toolchain(hlsl));
    }
  }
  modules_ = std::make_unique<ModuleMemo>(kRememberedModules);
  clocks_ = std::make_unique<StageClock[]>(stages_.size() + 2);
}

Pipeline::~Pipeline() = default;

template <typename Work>
auto Pipeline::timed(std::size_t i, Work&& work, bool counted) const {
  const auto start = std::chrono::steady_clock::now();
  auto result = work();
  const auto spent = std::chrono::steady_clock::now() - start;
  clocks_[i].nanoseconds += std::chrono::duration_cast<std::chrono::nanoseconds>(spent).count();
  if (counted) ++clocks_[i].runs;
  return result;
}

Status Pipeline::run(ShaderJob& job) const {
  PENUMBRA_TRY(timed(0, [&] { return run_stage(*stages_.front(), job); }));
  const std::size_t cache_clock = stages_.size();
  std::string key;
  if (cache_) {
    const bool restored = timed(cache_clock, [&] {
      key = cache_->key(job);
      return cache_->restore(key, job, *write_root_);
    });
    if (restored) {
      job.from_cache = true;
      return {};
    }
  }
  PENUMBRA_TRY(make_module(job));
  PENUMBRA_TRY(run_stages(1 + kModuleStages, stages_.size(), job));
  if (cache_) {
    const auto store = [&] {
      cache_->store(key, job, *write_root_);
      return true;
    };
    timed(cache_clock, store, /*counted=*/false);  // counted when it was looked up
  }
  return {};
}

Status Pipeline::run_stages(std::size_t first, std::size_t last, ShaderJob& job) const {
  for (std::size_t i = first; i < last; ++i) {
    PENUMBRA_TRY(timed(i, [&] { return run_stage(*stages_[i], job); }));
  }
  return {};
}

// A failed module is not remembered: each job that needs it fails with an
// error naming its own target.
Status Pipeline::make_module(ShaderJob& job) const {
  const std::size_t memo_clock = stages_.size() + 1;
  std::string key;
  const auto find = [&] {
    key = module_key(job);
    return modules_->find(key);
  };
  if (std::optional<Module> made = timed(memo_clock, find, false)) {
    job.spirv = std::move(made->spirv);
    job.interface = std::move(made->interface);
    ++clocks_[memo_clock].runs;
    return {};
  }
  PENUMBRA_TRY(run_stages(1, 1 + kModuleStages, job));
  modules_->add(key, {job.spirv, job.interface});
  return {};
}

std::vector<StageTime> Pipeline::profile() const {
  std::vector<StageTime> out;
  const auto row = [&](std::string_view name, std::size_t i) {
    const double seconds = static_cast<double>(clocks_[i].nanoseconds.load()) * 1e-9;
    out.push_back({std::string(name), seconds, clocks_[i].runs.load()});
  };
  for (std::size_t i = 0; i < stages_.size(); ++i) row(stages_[i]->name(), i);
  row("shared-module", stages_.size() + 1);
  if (cache_) row("cache", stages_.size());
  return out;
}

}  // namespace penumbra
