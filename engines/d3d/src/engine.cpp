#include "penumbra/d3d/engine.hpp"

#include <unistd.h>

#include "host_process.hpp"
#include "job.hpp"
#include "pass_binding.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/image_checks.hpp"
#include "penumbra/support/minmax_levels.hpp"

namespace penumbra {
namespace {

using d3d::DrawGeometry;
using d3d::DrawTarget;
using d3d::Job;
using d3d::PassTextures;

// A target of the runtime, for the reflection's format names.
Target api_target(D3dRuntime runtime) {
  switch (runtime) {
    case D3dRuntime::d3d9:
      return Target::hlsl_dx9;
    case D3dRuntime::d3d10:
      return Target::hlsl_dx10;
    case D3dRuntime::d3d11:
      break;
  }
  return Target::hlsl_dx11;
}

// The render target a pass draws into: its format and floats per texel.
struct PassTarget {
  std::string format;
  int channels = 0;
};

Result<PassTarget> pass_target(D3dRuntime runtime, const D3dPass& pass, const std::string& where) {
  if (pass.reflection.render_targets.empty()) {
    return make_error(Error::Kind::bad_input, where, "its reflection lists no render target");
  }
  const std::string& format = pass.reflection.render_targets.front().format;
  const auto parsed = parse_api_format(api_target(runtime), format);
  if (!parsed) {
    return make_error(Error::Kind::bad_input, where,
                      "render target format '" + format + "' is not one of " +
                          allowed_api_formats(api_target(runtime)));
  }
  return PassTarget{format, static_cast<int>(texel_components(*parsed))};
}

// `triangles` (x, y, z per vertex) as a vertex buffer of the job's.
DrawGeometry triangle_list(Job& job, const std::vector<std::array<float, 3>>& triangles) {
  std::vector<float> vertices;
  for (const auto& v : triangles) vertices.insert(vertices.end(), v.begin(), v.end());
  return {job.vertices(vertices), static_cast<unsigned>(triangles.size())};
}

// A pass drawn over a whole target of `width` x `height`.
DrawTarget whole(int colour, int width, int height) {
  return {colour, 0, std::nullopt, width, height, std::nullopt, std::nullopt};
}

// The one triangle every full-screen pass draws, as a vertex buffer of the job's.
DrawGeometry full_screen_triangle(Job& job) {
  return {job.vertices(std::vector<float>(kFullScreenTriangle.begin(), kFullScreenTriangle.end())),
          3};
}

// The receivers and the full-screen triangle every screen pass reads.
struct ScreenInputs {
  int receivers = 0;
  DrawGeometry triangle;
};

ScreenInputs screen_inputs(Job& job, const FloatImage& receivers) {
  const int id = job.texture(api_format(api_target(job.runtime()), TextureFormat::rgba32_float),
                             receivers.width, receivers.height, 1, "input");
  job.upload(id, 0, receivers_to_rgba(receivers));
  return {id, full_screen_triangle(job)};
}

// The map as a pass reads it: shadow_depth and shadow_cmp, through its own
// view format where it has one.
PassTextures map_textures(const D3dMap& map) {
  return {{TextureId::shadow_depth, {map.id, map.view_format}},
          {TextureId::shadow_cmp, {map.id, map.view_format}}};
}

// `pass` (the query or the deferred pass) drawn over a whole width x height
// target with `textures`, screen_size set to that size; the job run and its
// (visibility, texel reads) read back.
Result<D3dQueryOutput> draw_visibility(Job& job, const D3dPass& pass, const std::string& where,
                                       const PassTextures& textures, const ParamBlock& params,
                                       int width, int height, DrawGeometry triangle) {
  auto format = pass_target(job.runtime(), pass, where);
  if (!format) return format.error();
  ParamBlock screen_params = params;
  screen_params["screen_size"] = size_vec4(width, height);
  const int output = job.texture(format->format, width, height, 1, "target");
  PENUMBRA_TRY(d3d::draw_pass(job, pass, where, textures, screen_params,
                              whole(output, width, height), triangle));
  const std::size_t read = job.read(output, 0, width, height, format->channels);
  PENUMBRA_TRY(job.run());
  const FloatImage texels = job.take(read);
  return D3dQueryOutput{channel(texels, 0), channel(texels, 1)};
}

// Draws the min-max chain of `map` (docs/shader-interface.md): each level
// into a target of its own, read by the next reduce pass, then copied into
// the mipmapped chain, which no draw ever writes while it is read.
Result<int> draw_minmax_chain(Job& job, const D3dMinmaxPasses& passes, const D3dMap& map,
                              const ParamBlock& params, std::vector<LevelSize>& sizes) {
  auto format = pass_target(job.runtime(), passes.init, "the minmax_init pass");
  if (!format) return format.error();
  sizes = minmax_level_sizes(map.width, map.height);
  const int side = minmax_chain_side(map.width, map.height);
  const int chain =
      job.texture(format->format, side, side, static_cast<int>(sizes.size()), "target");
  const DrawGeometry geometry = full_screen_triangle(job);
  LevelSize source{map.width, map.height};
  int source_level = 0;
  for (std::size_t l = 0; l < sizes.size(); ++l) {
    const LevelSize size = sizes[l];
    const int level = job.texture(format->format, size.width, size.height, 1, "target");
    ParamBlock level_params = params;
    level_params["source_size"] = size_vec4(source.width, source.height);
    level_params["screen_size"] = size_vec4(size.width, size.height);
    PassTextures textures = map_textures(map);
    if (l > 0) textures[TextureId::minmax_source] = {source_level, {}};
    const D3dPass& pass = l == 0 ? passes.init : passes.reduce;
    const std::string where =
        std::string(l == 0 ? "the minmax_init pass" : "the minmax_reduce pass") +
        " (min-max level " + std::to_string(l + 1) + ")";
    PENUMBRA_TRY(d3d::draw_pass(job, pass, where, textures, level_params,
                                whole(level, size.width, size.height), geometry));
    job.copy(level, 0, chain, static_cast<int>(l));
    source = size;
    source_level = level;
  }
  return chain;
}

// `map`'s textures, with its min-max chain drawn by `minmax` when given.
Result<PassTextures> map_and_minmax(Job& job, const D3dMap& map,
                                    const std::optional<D3dMinmaxPasses>& minmax,
                                    const ParamBlock& params) {
  PassTextures textures = map_textures(map);
  if (minmax) {
    std::vector<LevelSize> sizes;
    PENUMBRA_TRY_ASSIGN(const int chain, draw_minmax_chain(job, *minmax, map, params, sizes));
    textures[TextureId::shadow_minmax] = {chain, {}};
  }
  return textures;
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
                     std::unique_ptr<d3d::HostProcess> host, std::string description)
    : session_(std::move(session)),
      options_(std::move(options)),
      runtime_(options_.runtime),
      host_(std::move(host)),
      description_(std::move(description)) {}

D3dEngine::~D3dEngine() {
  if (host_) static_cast<void>(host_->write("quit\n"));
}

Result<std::unique_ptr<D3dEngine>> D3dEngine::create(std::shared_ptr<WineSession> session,
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
  auto host_process = std::make_unique<d3d::HostProcess>(std::move(*process));
  // A new prefix is made on the first start: that takes a while.
  auto hello = host_process->read_line(std::chrono::seconds(180));
  if (!hello) return hello.error();
  if (hello->rfind("ready ", 0) != 0) {
    return make_error(Error::Kind::device, std::string(to_string(options.runtime)),
                      "the host could not start it: " + *hello +
                          " (Wine's log: " + session->log().string() + ")");
  }
  return std::unique_ptr<D3dEngine>(
      new D3dEngine(std::move(session), options, std::move(host_process), hello->substr(6)));
}

Status D3dEngine::run(d3d::Job& job) {
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
  Job job(*this);
  D3dMap map;
  map.width = width;
  map.height = height;
  // A reversed-Z map is cleared to 0, its far plane, and keeps the greater depth.
  const bool reversed = depth.reflection.map_encoding == MapEncoding::perspective_reversed;
  const float far = reversed ? 0.0f : 1.0f;
  DrawTarget target{std::nullopt, 0, std::nullopt, width, height, std::nullopt, far, reversed};
  if (runtime_ == D3dRuntime::d3d9) {
    // The whitepaper's map: an R32F colour target, and a depth buffer that
    // only depth-tests (docs/engines/d3d9.md).
    auto colour = pass_target(runtime_, depth, "the depth pass");
    if (!colour) return colour.error();
    map.format = colour->format;
    map.id = job.texture(map.format, width, height, 1, "target");
    target.colour = map.id;
    target.clear_colour = std::array<float, 4>{far, far, far, far};
    target.depth = job.texture(depth.reflection.depth_target, width, height, 1, "depth");
  } else {
    // One typeless texture: written through its depth view, read through
    // R32_FLOAT views (docs/engines/d3d10.md), or an engine's D24 or D16
    // map's unorm views ("Using your own shadow map").
    switch (map_format) {
      case DepthFormat::d32_float:
        map.format = api_format(api_target(runtime_), TextureFormat::d32_float);
        break;
      case DepthFormat::d24_unorm:
        map.format = "DXGI_FORMAT_R24G8_TYPELESS";
        map.view_format = "DXGI_FORMAT_R24_UNORM_X8_TYPELESS";
        break;
      case DepthFormat::d16_unorm:
        map.format = "DXGI_FORMAT_R16_TYPELESS";
        map.view_format = "DXGI_FORMAT_R16_UNORM";
        break;
    }
    map.id = job.texture(map.format, width, height, 1, "depth");
    target.depth = map.id;
  }
  job.keep(map.id);
  const DrawGeometry geometry = triangle_list(job, triangles);
  PENUMBRA_TRY(d3d::draw_pass(job, depth, "the depth pass", {}, params, target, geometry));
  const std::size_t read = job.read(map.id, 0, width, height, 1);
  if (Status s = job.run(); !s) {
    release(map);
    return s.error();
  }
  map.normalized = job.take(read);
  return map;
}

Result<FloatImage> D3dEngine::run_surface(const D3dPass& surface,
                                          const std::vector<std::array<float, 3>>& triangles,
                                          const D3dMap& map, int width, int height,
                                          const ParamBlock& params,
                                          const std::optional<D3dMinmaxPasses>& minmax) {
  Job job(*this);
  PENUMBRA_TRY_ASSIGN(const PassTextures textures, map_and_minmax(job, map, minmax, params));
  auto format = pass_target(runtime_, surface, "the surface pass");
  if (!format) return format.error();
  const int output = job.texture(format->format, width, height, 1, "target");
  // The camera's own depth buffer: the nearest surface wins, as in an engine.
  const std::string depth_format =
      runtime_ == D3dRuntime::d3d9
          ? surface.reflection.depth_target
          : std::string(api_format(api_target(runtime_), TextureFormat::d32_float));
  const int depth = job.texture(depth_format, width, height, 1, "depth");
  const DrawGeometry geometry = triangle_list(job, triangles);
  const DrawTarget target{
      output, 0, depth, width, height, std::array<float, 4>{1.0f, 1.0f, 1.0f, 1.0f}, 1.0f, false};
  PENUMBRA_TRY(
      d3d::draw_pass(job, surface, "the surface pass", textures, params, target, geometry));
  const std::size_t read = job.read(output, 0, width, height, format->channels);
  PENUMBRA_TRY(job.run());
  return job.take(read);
}

void D3dEngine::release(const D3dMap& map) {
  pending_releases_ += "release " + std::to_string(map.id) + "\n";
}

Result<std::vector<FloatImage>> D3dEngine::build_minmax(const D3dMinmaxPasses& passes,
                                                        const D3dMap& map,
                                                        const ParamBlock& params) {
  Job job(*this);
  std::vector<LevelSize> sizes;
  auto chain = draw_minmax_chain(job, passes, map, params, sizes);
  if (!chain) return chain.error();
  std::vector<std::size_t> reads;
  for (std::size_t l = 0; l < sizes.size(); ++l) {
    reads.push_back(job.read(*chain, static_cast<int>(l), sizes[l].width, sizes[l].height, 2));
  }
  PENUMBRA_TRY(job.run());
  std::vector<FloatImage> levels;
  for (std::size_t read : reads) levels.push_back(job.take(read));
  return levels;
}

Result<D3dQueryOutput> D3dEngine::run_query(const D3dQueryPasses& passes, const D3dMap& map,
                                            const FloatImage& receivers, const ParamBlock& params) {
  Job job(*this);
  const ScreenInputs screen = screen_inputs(job, receivers);
  PENUMBRA_TRY_ASSIGN(PassTextures textures, map_and_minmax(job, map, passes.minmax, params));
  textures[TextureId::receivers] = {screen.receivers, {}};
  return draw_visibility(job, passes.query, "the query pass", textures, params, receivers.width,
                         receivers.height, screen.triangle);
}

Result<D3dQueryOutput> D3dEngine::run_deferred(const D3dPass& deferred, const D3dMap& map,
                                               const FloatImage& camera_depth,
                                               const ParamBlock& params,
                                               const std::optional<D3dMinmaxPasses>& minmax) {
  PENUMBRA_TRY(check_normalized_depth(camera_depth));
  Job job(*this);
  PENUMBRA_TRY_ASSIGN(PassTextures textures, map_and_minmax(job, map, minmax, params));
  const int camera = job.texture(api_format(api_target(runtime_), TextureFormat::r32_float),
                                 camera_depth.width, camera_depth.height, 1, "input");
  job.upload(camera, 0, camera_depth.data);
  textures[TextureId::camera_depth] = {camera, {}};
  return draw_visibility(job, deferred, "the deferred pass", textures, params, camera_depth.width,
                         camera_depth.height, full_screen_triangle(job));
}

Result<D3dScreenBlurOutput> D3dEngine::run_screen_blur(const D3dScreenBlurPasses& passes,
                                                       const D3dMap& map,
                                                       const FloatImage& receivers,
                                                       const FloatImage& scene_colour,
                                                       const ParamBlock& params) {
  Job job(*this);
  const int width = receivers.width;
  const int height = receivers.height;
  const ScreenInputs screen = screen_inputs(job, receivers);
  const int colour = job.texture(api_format(api_target(runtime_), TextureFormat::rgba32_float),
                                 width, height, 1, "input");
  job.upload(colour, 0, receivers_to_rgba(scene_colour));
  PassTextures textures = map_textures(map);
  textures[TextureId::receivers] = {screen.receivers, {}};
  textures[TextureId::scene_colour] = {colour, {}};
  ParamBlock screen_params = params;
  screen_params["screen_size"] = size_vec4(width, height);
  // Each pass after the query reads the one before as screen_factor.
  struct Step {
    const D3dPass* pass;
    const char* where;
  };
  const Step steps[] = {{&passes.query, "the query pass"},
                        {&passes.blur_h, "the blur_h pass"},
                        {&passes.blur_v, "the blur_v pass"},
                        {&passes.composite, "the composite pass"}};
  std::vector<std::size_t> reads;  // every target but blur_h's
  for (const Step& step : steps) {
    auto format = pass_target(runtime_, *step.pass, step.where);
    if (!format) return format.error();
    const int output = job.texture(format->format, width, height, 1, "target");
    PENUMBRA_TRY(d3d::draw_pass(job, *step.pass, step.where, textures, screen_params,
                                whole(output, width, height), screen.triangle));
    textures[TextureId::screen_factor] = {output, {}};
    if (step.pass != &passes.blur_h) {
      reads.push_back(job.read(output, 0, width, height, format->channels));
    }
  }
  PENUMBRA_TRY(job.run());
  const FloatImage factor = job.take(reads[0]);
  return D3dScreenBlurOutput{channel(factor, 0), channel(factor, 1), channel(job.take(reads[1]), 0),
                             job.take(reads[2])};
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
