// D3dEngine: runs a Direct3D target's bytecode (.d3dbc, .dxbc) on a real
// Direct3D 9, 10 or 11 runtime: Wine's d3d9/d3d10/d3d11 on Linux, through
// penumbra_d3d_host.exe (runtime/d3d/host). Every pass is bound by its
// reflection, index.json's `reflection.<pass>.<target>`, as a Direct3D
// engine that drops the library in does: registers, formats, sampler states
// and input layouts come from the record alone, and D3D9's gl_HalfPixel is
// set as docs/engines/d3d9.md says. The engine draws the depth pass, the
// min-max chain, the query, a variant's whole pass list (run_passes: a
// chain such as screen_blur's), and an engine's own geometry around a
// function form, and reads targets back; no call names a technique.
//
// Lifecycle: create() starts one host process for the runtime in `session`
// and waits until it has made its device; launch() starts it without
// waiting, so that Wine boots while the caller does other work, and
// ready() (or the first draw) waits. Every later call is one run of the pass driver
// (penumbra/runtime/ pass_driver.hpp) on a device that writes one job list and sends it to the host
// when it reads back (no process per draw); calls come from one thread at a time. Destroying the
// engine ends the host. Every failure is a returned Error, never an exception.
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/d3d/wine_session.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

namespace d3d {
class HostProcess;
class Job;
}  // namespace d3d

enum class D3dRuntime { d3d9, d3d10, d3d11 };

// "d3d9", "d3d10", "d3d11": verify.json's backend names.
std::string_view to_string(D3dRuntime runtime);
// The runtime an engine loads `target`'s bytecode on: hlsl_dx9 on d3d9,
// hlsl_dx10 on d3d10, hlsl_dx11 on d3d11; none for other targets.
std::optional<D3dRuntime> runtime_for(Target target);

struct D3dEngineOptions {
  D3dRuntime runtime = D3dRuntime::d3d11;
  // penumbra_d3d_host.exe; "" takes default_d3d_host().
  std::filesystem::path host;
  // The longest one job list may take before the host counts as hung.
  std::chrono::seconds job_timeout{300};
};

// Where penumbra_d3d_host.exe is: PENUMBRA_D3D_HOST when set, else beside the
// running executable, else the installed libexec folder, else the build
// tree's; empty when none exists.
std::filesystem::path default_d3d_host();
// Why no host can be started, naming the cause a user can act on (a
// PENUMBRA_D3D_HOST that names nothing, a build tree that did not build it,
// or one configured without mingw-w64); empty when default_d3d_host() exists.
std::string why_no_d3d_host();

// One pass's bytecode and reflection. The engine reads the reflection
// through the reference; it must outlive the call.
struct D3dPass {
  std::filesystem::path vert;  // the vertex stage's bytecode
  std::filesystem::path frag;  // the pixel stage's bytecode
  const PassReflection& reflection;
};

struct D3dMinmaxPasses {
  D3dPass init;    // minmax_init: the map -> level 1
  D3dPass reduce;  // minmax_reduce: level l - 1 -> level l
};

struct D3dQueryPasses {
  D3dPass query;
  std::optional<D3dMinmaxPasses> minmax = std::nullopt;  // when the query reads shadow_minmax
};

// A shadow map the depth pass drew, kept on the host until release().
struct D3dMap {
  int id = 0;
  int width = 0;
  int height = 0;
  std::string format;  // as created: the depth pass's map format
  // The shader-resource view format it is read through where that is not
  // the reflection's: an engine's D24 or D16 map (R24_UNORM_X8_TYPELESS,
  // R16_UNORM); empty for D32.
  std::string view_format;
  FloatImage normalized;  // its texels, read back: z * depth_scale
};

struct D3dQueryOutput {
  FloatImage visibility;   // .x
  FloatImage texel_reads;  // .y
};

class D3dEngine {
 public:
  // Starts the host for `options.runtime` and waits for its device. Errors:
  // device (no host, Wine cannot create the device; the host's own words).
  static Result<std::unique_ptr<D3dEngine>> create(std::shared_ptr<WineSession> session,
                                                   const D3dEngineOptions& options);
  // Starts the host without waiting for it. Errors: as create()'s for a
  // host that cannot start; the device's own at ready().
  static Result<std::unique_ptr<D3dEngine>> launch(std::shared_ptr<WineSession> session,
                                                   const D3dEngineOptions& options);
  // Waits until the host has made its device (at once after the first
  // time). Errors: as create()'s, the same on every later call and draw.
  Status ready();
  D3dEngine(const D3dEngine&) = delete;
  D3dEngine& operator=(const D3dEngine&) = delete;
  ~D3dEngine();

  // "Direct3D 9 on <adapter>" as the host reports it; empty before ready().
  const std::string& description() const { return description_; }
  D3dRuntime runtime() const { return runtime_; }

  // Draws `triangles` (light-view x, y, z per vertex, three per triangle)
  // with the depth pass into a new width x height map, as
  // docs/engines/<runtime>.md creates it, and reads it back. On Direct3D
  // 10/11 `map_format` is the map's depth texture (D24 and D16 as an engine's,
  // through their unorm views); Direct3D 9's map is its R32F target.
  Result<D3dMap> render_depth(const D3dPass& depth,
                              const std::vector<std::array<float, 3>>& triangles, int width,
                              int height, const ParamBlock& params,
                              DepthFormat map_format = DepthFormat::d32_float);
  void release(const D3dMap& map);
  // `normalized` (one channel, row 0 first, values in [0, 1]) held on the
  // host as a map the depth pass drew into a D32 map (Direct3D 9: its R32F
  // target), read back: an engine's own map, such as an atlas of several
  // lights' tiles. Errors: bad_input (values outside [0, 1]); device.
  Result<D3dMap> upload_map(const FloatImage& normalized);

  // The min-max chain of `map` built by `passes` (each level drawn into a
  // target of its own, then copied into the mipmapped chain), read back:
  // levels 1..N as support/minmax_levels.hpp sizes them.
  Result<std::vector<FloatImage>> build_minmax(const D3dMinmaxPasses& passes, const D3dMap& map,
                                               const ParamBlock& params);

  // The query over `receivers` ((u, v, z_r) per pixel, 3 or 4 channels) on
  // `map`, after the min-max chain when the query reads it.
  Result<D3dQueryOutput> run_query(const D3dQueryPasses& passes, const D3dMap& map,
                                   const FloatImage& receivers, const ParamBlock& params);

  // A deferred pass (docs/deferred-mask.md) on `map`, into a target of
  // `camera_depth`'s size: `camera_depth` is one channel of the camera's
  // depth as stored, row 0 first, uploaded as an R32 float texture (what a
  // Direct3D 10/11 engine's typeless depth buffer's shader view reads, and
  // what a Direct3D 9 engine draws its depth into). `params` holds the
  // pass's matrices besides ShadowParams' members. `minmax` builds the
  // min-max chain first, for a pass that reads it.
  Result<D3dQueryOutput> run_deferred(const D3dPass& deferred, const D3dMap& map,
                                      const FloatImage& camera_depth, const ParamBlock& params,
                                      const std::optional<D3dMinmaxPasses>& minmax = std::nullopt);

  // Runs `passes`, a variant's pass list without its depth pass, on the
  // pass driver (penumbra/runtime/pass_driver.hpp) on `map`: each pass with
  // its bytecode from `programs`, full-screen over the screen `images`
  // gives (the receivers, or a camera's depth for a deferred pass; the scene
  // colour for a composite), each target the screen's size with screen_size
  // set to it; the min-max passes, where listed, build the min-max chain
  // first. One job list; returns every screen pass's target, all its
  // channels.
  Result<runtime::PassOutputs> run_passes(std::span<const PassKind> passes,
                                          const std::map<PassKind, D3dPass>& programs,
                                          const D3dMap& map, const runtime::ScreenImages& images,
                                          const ParamBlock& params);

  // Draws `triangles` (a triangle list in whatever space the vertex
  // shader takes, at the reflection's vertex input) with `surface`, an
  // engine's own shaders whose pixel shader calls a variant's function
  // form (docs/function-form.md), into a width x height target in the
  // reflection's render-target format with a depth buffer of its own (both
  // cleared to 1, depth test LESS), `map` bound as the function form's
  // textures (with the min-max chain `minmax` builds, for a function that
  // reads it), and reads the target back.
  Result<FloatImage> run_surface(const D3dPass& surface,
                                 const std::vector<std::array<float, 3>>& triangles,
                                 const D3dMap& map, int width, int height, const ParamBlock& params,
                                 const std::optional<D3dMinmaxPasses>& minmax = std::nullopt);

 private:
  friend class d3d::Job;  // creates ids, shares the shader caches, runs itself

  D3dEngine(std::shared_ptr<WineSession> session, D3dEngineOptions options,
            std::unique_ptr<d3d::HostProcess> host);
  // Sends `job`'s commands and waits for the host's answer.
  Status run(d3d::Job& job);
  int next_id() { return next_id_++; }

  std::shared_ptr<WineSession> session_;
  D3dEngineOptions options_;
  D3dRuntime runtime_;
  std::unique_ptr<d3d::HostProcess> host_;
  bool answered_ = false;                 // the host has said "ready"
  std::string description_;               // from that line
  std::optional<Error> failed_to_start_;  // its answer instead, or its silence
  int next_id_ = 1;
  std::map<std::string, int> shaders_;            // bytecode (its bytes) -> host id, loaded once
  std::map<std::string, int> constant_textures_;  // D3D9 disks: texels -> host id
  std::string pending_releases_;  // finished jobs' resources, released by the next job
};

}  // namespace penumbra
