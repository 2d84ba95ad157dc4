#include "penumbra/d3d/engine.hpp"

#include <unistd.h>

#include "d3d_device.hpp"
#include "host_process.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra {
namespace {

using d3d::D3dDevice;

// The min-max passes before `pass` when given: a pass that reads the mip
// gets it built first, on the map the call names.
std::vector<PassKind> with_minmax(const std::optional<D3dMinmaxPasses>& minmax, PassKind pass,
                                  std::map<PassKind, D3dPass>& programs) {
  if (!minmax) return {pass};
  programs.emplace(PassKind::minmax_init, minmax->init);
  programs.emplace(PassKind::minmax_reduce, minmax->reduce);
  return {PassKind::minmax_init, PassKind::minmax_reduce, pass};
}

// A query's or a deferred pass's (visibility, texel reads), split.
D3dQueryOutput visibility_of(const runtime::PassOutputs& outputs) {
  const FloatImage& target = outputs.targets.front().second;
  return D3dQueryOutput{channel(target, 0), channel(target, 1)};
}

// `map`, which `device` drew or uploaded and the host keeps, read back into
// its D3dMap; released again where the read fails.
Result<D3dMap> kept_map(D3dEngine& engine, D3dDevice& device, runtime::Texture map) {
  D3dMap out = device.map(map);
  auto texels = device.read(map);
  if (!texels) {
    engine.release(out);
    return texels.error();
  }
  out.normalized = std::move(*texels);
  return out;
}

}  // namespace

std::string_view to_string(D3dRuntime runtime) {
  switch (runtime) {
    case D3dRuntime::d3d9:
      return "d3d9";
    case D3dRuntime::d3d10:
      return "d3d10";
    case D3dRuntime::d3d11:
      break;
  }
  return "d3d11";
}

std::optional<D3dRuntime> runtime_for(Target target) {
  switch (target) {
    case Target::hlsl_dx9:
      return D3dRuntime::d3d9;
    case Target::hlsl_dx10:
      return D3dRuntime::d3d10;
    case Target::hlsl_dx11:
      return D3dRuntime::d3d11;
    default:
      return std::nullopt;
  }
}

D3dEngine::D3dEngine(std::shared_ptr<WineSession> session, D3dEngineOptions options,
                     std::unique_ptr<d3d::HostProcess> host)
    : session_(std::move(session)),
      options_(std::move(options)),
      runtime_(options_.runtime),
      host_(std::move(host)) {}

D3dEngine::~D3dEngine() {
  if (host_) static_cast<void>(host_->write("quit\n"));
}

Result<std::unique_ptr<D3dEngine>> D3dEngine::create(std::shared_ptr<WineSession> session,
                                                     const D3dEngineOptions& options) {
  PENUMBRA_TRY_ASSIGN(std::unique_ptr<D3dEngine> engine, launch(std::move(session), options));
  PENUMBRA_TRY(engine->ready());
  return engine;
}

Result<std::unique_ptr<D3dEngine>> D3dEngine::launch(std::shared_ptr<WineSession> session,
                                                     const D3dEngineOptions& options) {
  const std::filesystem::path host = options.host.empty() ? default_d3d_host() : options.host;
  if (host.empty() || !std::filesystem::exists(host)) {
    const std::string why = options.host.empty() ? why_no_d3d_host() : std::string();
    return make_error(Error::Kind::device, host.empty() ? "penumbra_d3d_host.exe" : host.string(),
                      why.empty() ? "does not exist" : why);
  }
  auto process = d3d::HostProcess::start(
      {session->wine(), host.string(), std::string(to_string(options.runtime))},
      session->environment(), session->log().string());
  if (!process) return process.error();
  return std::unique_ptr<D3dEngine>(new D3dEngine(
      std::move(session), options, std::make_unique<d3d::HostProcess>(std::move(*process))));
}

Status D3dEngine::ready() {
  if (failed_to_start_) return *failed_to_start_;
  if (answered_) return {};
  // A new prefix is made on the first start: that takes a while.
  auto hello = host_->read_line(std::chrono::seconds(180));
  if (!hello) {
    failed_to_start_ = hello.error();
  } else if (hello->rfind("ready ", 0) != 0) {
    failed_to_start_ = make_error(Error::Kind::device, std::string(to_string(options_.runtime)),
                                  "the host could not start it: " + *hello +
                                      " (Wine's log: " + session_->log().string() + ")");
  } else {
    description_ = hello->substr(6);
    answered_ = true;
    return {};
  }
  return *failed_to_start_;
}

Status D3dEngine::run(d3d::Job& job) {
  PENUMBRA_TRY(ready());
  const std::string tag = std::to_string(job.number_);
  std::string text = std::move(pending_releases_) + job.commands_ + "sync " + tag + "\n";
  pending_releases_.clear();
  PENUMBRA_TRY(host_->write(text));
  auto answer = host_->read_line(options_.job_timeout);
  if (!answer) return answer.error();
  if (*answer == "ok " + tag) return {};
  const std::string prefix = "error " + tag + " ";
  return make_error(Error::Kind::device, description_,
                    answer->rfind(prefix, 0) == 0 ? answer->substr(prefix.size())
                                                  : "unexpected answer '" + *answer + "'");
}

Result<D3dMap> D3dEngine::render_depth(const D3dPass& depth,
                                       const std::vector<std::array<float, 3>>& triangles,
                                       int width, int height, const ParamBlock& params,
                                       DepthFormat map_format) {
  D3dDevice device(*this);
  PENUMBRA_TRY_ASSIGN(
      const runtime::Texture drawn,
      runtime::draw_map(device, device.load(depth), triangles, width, height, map_format, params));
  return kept_map(*this, device, drawn);
}

Result<D3dMap> D3dEngine::upload_map(const FloatImage& normalized) {
  D3dDevice device(*this);
  PENUMBRA_TRY_ASSIGN(const runtime::Texture uploaded,
                      device.upload(TextureId::shadow_depth, normalized));
  return kept_map(*this, device, uploaded);
}

Result<FloatImage> D3dEngine::run_surface(const D3dPass& surface,
                                          const std::vector<std::array<float, 3>>& triangles,
                                          const D3dMap& map, int width, int height,
                                          const ParamBlock& params,
                                          const std::optional<D3dMinmaxPasses>& minmax) {
  PENUMBRA_TRY(runtime::check_triangle_list(triangles, "surface pass"));
  D3dDevice device(*this);
  runtime::PassPrograms programs;
  std::vector<PassKind> passes;
  if (minmax) {
    programs = {{PassKind::minmax_init, device.load(minmax->init)},
                {PassKind::minmax_reduce, device.load(minmax->reduce)}};
    passes = {PassKind::minmax_init, PassKind::minmax_reduce};
  }
  runtime::PassInputs inputs;
  inputs.map = device.adopt(map);
  inputs.params = params;
  PENUMBRA_TRY_ASSIGN(runtime::PassResults built,
                      runtime::run_passes(device, passes, programs, inputs));
  PENUMBRA_TRY_ASSIGN(runtime::Drawn drawn,
                      runtime::draw_surface(device, device.load(surface), triangles, width, height,
                                            *inputs.map, built.mip, params));
  return device.read(drawn.target);
}

void D3dEngine::release(const D3dMap& map) {
  pending_releases_ += "release " + std::to_string(map.id) + "\n";
}

Result<std::vector<FloatImage>> D3dEngine::build_minmax(const D3dMinmaxPasses& passes,
                                                        const D3dMap& map,
                                                        const ParamBlock& params) {
  D3dDevice device(*this);
  const runtime::PassPrograms programs = {{PassKind::minmax_init, device.load(passes.init)},
                                          {PassKind::minmax_reduce, device.load(passes.reduce)}};
  runtime::PassInputs inputs;
  inputs.map = device.adopt(map);
  inputs.params = params;
  const PassKind list[] = {PassKind::minmax_init, PassKind::minmax_reduce};
  PENUMBRA_TRY_ASSIGN(runtime::PassResults results,
                      runtime::run_passes(device, list, programs, inputs));
  return device.read_all(results.levels);
}

Result<runtime::PassOutputs> D3dEngine::run_passes(std::span<const PassKind> passes,
                                                   const std::map<PassKind, D3dPass>& programs,
                                                   const D3dMap& map,
                                                   const runtime::ScreenImages& images,
                                                   const ParamBlock& params) {
  D3dDevice device(*this);
  runtime::PassPrograms loaded;
  for (const auto& [pass, program] : programs) loaded[pass] = device.load(program);
  runtime::PassInputs inputs;
  inputs.map = device.adopt(map);
  PENUMBRA_TRY(runtime::upload_screen(device, images, passes, inputs));
  inputs.params = params;
  return runtime::run_and_read(device, passes, loaded, inputs);
}

Result<D3dQueryOutput> D3dEngine::run_query(const D3dQueryPasses& passes, const D3dMap& map,
                                            const FloatImage& receivers, const ParamBlock& params) {
  std::map<PassKind, D3dPass> programs = {{PassKind::query, passes.query}};
  const std::vector<PassKind> list = with_minmax(passes.minmax, PassKind::query, programs);
  PENUMBRA_TRY_ASSIGN(runtime::PassOutputs outputs,
                      run_passes(list, programs, map, {.receivers = &receivers}, params));
  return visibility_of(outputs);
}

Result<D3dQueryOutput> D3dEngine::run_deferred(const D3dPass& deferred, const D3dMap& map,
                                               const FloatImage& camera_depth,
                                               const ParamBlock& params,
                                               const std::optional<D3dMinmaxPasses>& minmax) {
  std::map<PassKind, D3dPass> programs = {{PassKind::deferred, deferred}};
  const std::vector<PassKind> list = with_minmax(minmax, PassKind::deferred, programs);
  PENUMBRA_TRY_ASSIGN(runtime::PassOutputs outputs,
                      run_passes(list, programs, map, {.camera_depth = &camera_depth}, params));
  return visibility_of(outputs);
}

std::filesystem::path default_d3d_host() {
  if (const char* given = std::getenv("PENUMBRA_D3D_HOST"); given && *given) return given;
  std::vector<std::filesystem::path> candidates;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(self.parent_path() / "penumbra_d3d_host.exe");
    candidates.push_back(self.parent_path().parent_path() / "libexec" / "penumbra" /
                         "penumbra_d3d_host.exe");
  }
  candidates.push_back(PENUMBRA_D3D_HOST_BUILT);
  for (const auto& candidate : candidates) {
    if (std::filesystem::exists(candidate, ec)) return candidate;
  }
  return {};
}

std::string why_no_d3d_host() {
  if (const char* given = std::getenv("PENUMBRA_D3D_HOST"); given && *given) {
    std::error_code ec;
    if (std::filesystem::exists(given, ec)) return {};
    return std::string("PENUMBRA_D3D_HOST names ") + given + ", which does not exist";
  }
  if (!default_d3d_host().empty()) return {};
#ifdef PENUMBRA_D3D_HOST_BUILD_TREE
  // The build tree can make it: the target was not built, or not installed.
  return "penumbra_d3d_host.exe is neither beside this program, in its ../libexec/penumbra, "
         "nor built in " PENUMBRA_D3D_HOST_BUILD_TREE
         ": build it with cmake --build " PENUMBRA_D3D_HOST_BUILD_TREE
         " --target penumbra_d3d_host (penumbra_cli builds it "
         "too), or set PENUMBRA_D3D_HOST";
#else
  return "penumbra_d3d_host.exe was not built: CMake found no mingw-w64 C++ compiler when this "
         "build was configured (Debian: g++-mingw-w64-x86-64; install it and configure again), "
         "or set PENUMBRA_D3D_HOST";
#endif
}

}  // namespace penumbra
