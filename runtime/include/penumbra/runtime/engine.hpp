// Engine: runs Penumbra's passes on a Vulkan device (docs/runtime.md).
//
// Lifecycle: Engine::create() opens and checks a device; then any number of
// render_depth / upload_shadow_map / read_shadow_map / run_query calls, in any
// order, from one thread at a time (every call waits for its GPU work); then
// destroy the Engine. Every failure is a returned Error, never an exception.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "penumbra/runtime/program.hpp"
#include "penumbra/runtime/shadow_map.hpp"
#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

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
  // both images cleared to 1.0, depth test LESS, the fragment's output 0 into
  // the colour image and its depth into the depth image.
  Result<std::shared_ptr<ShadowMap>> render_depth(const PassProgram& depth,
                                                  std::span<const std::array<float, 3>> triangles,
                                                  int width, int height, const ParamBlock& params);

  // A new shadow map holding `normalized_depth` (one channel, every value in
  // [0, 1], row 0 first) in both of its images.
  Result<std::shared_ptr<ShadowMap>> upload_shadow_map(const FloatImage& normalized_depth);

  // The colour image's normalized depth, one channel, row 0 first.
  Result<FloatImage> read_shadow_map(const ShadowMap& map);

  // Runs a query program over one full-screen triangle into an R32_SFLOAT
  // target of the receivers' size and returns it (one channel). `receivers`
  // holds (u, v, z_r) per pixel in 3 or 4 channels.
  Result<FloatImage> run_query(const PassProgram& query, const ShadowMap& map,
                               const FloatImage& receivers, const ParamBlock& params);

 private:
  explicit Engine(std::unique_ptr<detail::Context> context);

  std::unique_ptr<detail::Context> context_;
};

}  // namespace penumbra
