// Engine: runs Penumbra's passes on a Vulkan device (docs/runtime.md).
//
// Lifecycle: Engine::create() opens and checks a device; then any number of
// render_depth / upload_shadow_map / read_shadow_map / build_minmax /
// read_minmax / run_query / run_passes / run_surface calls, in any order,
// from one thread at a time (every call waits for its GPU work; each is one
// run of the pass driver, penumbra/runtime/pass_driver.hpp, on the engine's
// device); then destroy the Engine. Every failure is a returned Error, never
// an exception. No call names a technique: a variant's passes are its
// model's pass list (TechniqueDescription::passes) run by run_passes.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"
#include "penumbra/vulkan/program.hpp"
#include "penumbra/vulkan/shadow_map.hpp"

namespace penumbra {

namespace detail {
struct Context;
}

struct EngineOptions {
  // "" picks lavapipe (a device whose name contains "llvmpipe") when present,
  // else the first device. Otherwise a device index ("0") or a case-insensitive
  // substring of the device name; the first match wins.
  std::string device;
  // Enables VK_LAYER_KHRONOS_validation when installed (a warning otherwise).
  // Validation warnings and errors become diagnostics; an error also fails the
  // call during which it was reported.
  bool validation = false;
};

struct DeviceInfo {
  std::string name;    // VkPhysicalDeviceProperties::deviceName
  std::string driver;  // driver name and info, e.g. "llvmpipe (Mesa 22.3.6 (LLVM 15.0.6))"
  std::uint32_t api_version = 0;  // VK_MAKE_API_VERSION encoded
  std::uint32_t sub_texel_precision_bits = 0;
};

// What a query pass wrote: its output's .x and .y, and how long it took.
struct QueryOutput {
  FloatImage visibility;  // .x: the visibility, one channel, the receivers' size
  // .y: the shadow-map and mip texels the pass counted as read per pixel
  // (docs/shader-interface.md), one channel.
  FloatImage texel_reads;
  // The draw's GPU time from timestamp queries; absent when the device's
  // queue writes no timestamps.
  std::optional<double> gpu_ms;
};

// A min-max mip built by Engine::build_minmax.
struct MinmaxBuild {
  int levels = 0;  // N: levels 1..N, level N 1x1
  // The level passes' GPU time summed (timestamps around each draw; the
  // copies into the mip are not included); absent without timestamps.
  std::optional<double> gpu_ms;
};

// A program for each pass of a list (Engine::run_passes); each must outlive the call.
using PassProgramMap = std::map<PassKind, const PassProgram*>;

class Engine {
 public:
  // Opens the device `options` selects and checks that it supports every
  // format and feature the passes use. Errors: bad_input when the selector
  // matches no device (the message lists them); device when there is no
  // device at all, a format feature is missing or a Vulkan call fails.
  static Result<std::unique_ptr<Engine>> create(const EngineOptions& options,
                                                DiagnosticConsumer diagnostics);
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  ~Engine();

  const DeviceInfo& device_info() const;

  // Draws `triangles` (light-view-space positions, a triangle list, no
  // culling) with the depth program into a new width x height shadow map:
  // both images cleared to 1.0, depth test LESS (a reversed-Z program, by its
  // reflection's map_encoding: 0.0 and GREATER), the fragment's output 0 into
  // the colour image and its depth into the depth image, a `depth_format`
  // image (D24 and D16 as an engine's hardware depth map is stored; programs
  // then read shadow_depth from it too). Errors: device where the device
  // cannot render, sample or copy that format.
  Result<std::shared_ptr<ShadowMap>> render_depth(
      const PassProgram& depth, std::span<const std::array<float, 3>> triangles, int width,
      int height, const ParamBlock& params, DepthFormat depth_format = DepthFormat::d32_float);

  // A new shadow map holding `normalized_depth` (one channel, every value in
  // [0, 1], row 0 first) in both of its images.
  Result<std::shared_ptr<ShadowMap>> upload_shadow_map(const FloatImage& normalized_depth);

  // The colour image's normalized depth, one channel, row 0 first.
  Result<FloatImage> read_shadow_map(const ShadowMap& map);
  // The depth image's values, likewise: what programs with `shadow_cmp` read
  // (a unorm image's codes as the floats its sampler returns).
  // The same as read_shadow_map() for a linear map; for an engine's hardware
  // depth (a map_encoding) the rasterizer's depth, where the colour image
  // holds the shader's encoding of the same surface.
  Result<FloatImage> read_shadow_depth(const ShadowMap& map);

  // Builds `map`'s min-max mip (replacing any it had) with a library's
  // minmax_init and minmax_reduce programs: level 1, ceil(W/2) x ceil(H/2),
  // by `init` reading the map as shadow_depth; each level l up to N by
  // `reduce` reading level l - 1 as minmax_source. Each pass gets `params`
  // with source_size set to the level it reads and screen_size to the level
  // it writes (W, H, 1/W, 1/H).
  Result<MinmaxBuild> build_minmax(ShadowMap& map, const PassProgram& init,
                                   const PassProgram& reduce, const ParamBlock& params);

  // The min-max mip's levels 1..N (index 0 is level 1), two channels (min,
  // max) each; a bad_input Error when the map has none.
  Result<std::vector<FloatImage>> read_minmax(const ShadowMap& map);

  // Runs a query program over one full-screen triangle into an R32G32_SFLOAT
  // target of the receivers' size and returns its .x (the visibility) and
  // .y (the texel reads), with the draw's GPU time. `receivers` holds
  // (u, v, z_r) per pixel in 3 or 4 channels. A program reading
  // shadow_minmax needs a map whose min-max mip is built.
  Result<QueryOutput> run_query_output(const PassProgram& query, const ShadowMap& map,
                                       const FloatImage& receivers, const ParamBlock& params);

  // Runs a deferred pass (docs/deferred-mask.md) as run_query_output runs
  // a query, over a target of `camera_depth`'s size: `camera_depth`, one
  // channel of the camera's depth buffer as stored, row 0 first, uploaded
  // as a D32_SFLOAT image and read as camera_depth. `params` holds the
  // pass's matrices besides ShadowParams' members. A pass reading
  // shadow_minmax needs a map whose min-max mip is built.
  Result<QueryOutput> run_deferred(const PassProgram& deferred, const ShadowMap& map,
                                   const FloatImage& camera_depth, const ParamBlock& params);

  // Runs `passes`, a variant's pass list without its depth pass (the map
  // is `map`), on the pass driver (penumbra/runtime/pass_driver.hpp): each
  // pass with its program from `programs`, full-screen, over the screen
  // `images` gives (the receivers, or a camera's depth for a deferred pass;
  // the scene colour for a composite), each target the screen's size with
  // screen_size set to it; the min-max passes, where listed, build `map`'s
  // mip (replacing any it had) as build_minmax does. Returns every screen
  // pass's target, all its channels, and the draws' GPU time. A pass
  // reading shadow_minmax needs the min-max passes before it or a map whose
  // mip is built. Errors as run_query_output's, naming the pass.
  Result<runtime::PassOutputs> run_passes(std::span<const PassKind> passes,
                                          const PassProgramMap& programs, ShadowMap& map,
                                          const runtime::ScreenImages& images,
                                          const ParamBlock& params);

  // Draws `triangles` (a triangle list in whatever space the program's
  // vertex stage takes, vec3 at location 0, no culling) with `surface`, an
  // engine's own program whose fragment stage calls a variant's function
  // form (docs/function-form.md), into a width x height
  // R32G32B32A32_SFLOAT target with a depth buffer of its own (both cleared
  // to 1.0, depth test LESS), the map bound as the function form's
  // textures (and its min-max mip, which must be built for a function that
  // reads shadow_minmax). Returns the four channels of output 0, row 0
  // first.
  Result<FloatImage> run_surface(const PassProgram& surface,
                                 std::span<const std::array<float, 3>> triangles,
                                 const ShadowMap& map, int width, int height,
                                 const ParamBlock& params);
  // run_query_output's visibility alone.
  Result<FloatImage> run_query(const PassProgram& query, const ShadowMap& map,
                               const FloatImage& receivers, const ParamBlock& params);

 private:
  explicit Engine(std::unique_ptr<detail::Context> context);

  std::unique_ptr<detail::Context> context_;
};

}  // namespace penumbra
