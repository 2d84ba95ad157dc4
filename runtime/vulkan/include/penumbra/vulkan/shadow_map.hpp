// ShadowMap: a shadow map on the device, made by an Engine.
#pragma once

#include <memory>
#include <optional>

namespace penumbra {

namespace detail {
struct ShadowMapImages;
}

// Two images of the same normalized depth d = z * depth_scale: a D32_SFLOAT
// depth image (sampled as `shadow_depth` and `shadow_cmp`) and an R32_SFLOAT
// colour image (sampled as `shadow_depth` by programs without `shadow_cmp`,
// the Direct3D 9 style); once Engine::build_minmax made it, the min-max mip
// (sampled as `shadow_minmax`). Only the Engine that made it can use it; it
// keeps that Engine's Vulkan device alive, so it may outlive the Engine.
class ShadowMap {
 public:
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;
  ~ShadowMap();

  int width() const;
  int height() const;
  // The min-max mip's levels (its top level N), or 0 when it has none.
  int minmax_levels() const;
  // The GPU time of the depth pass that drew it (Engine::render_depth), from
  // timestamp queries; absent for an uploaded map or without timestamps.
  std::optional<double> depth_gpu_ms() const;

 private:
  friend class Engine;
  explicit ShadowMap(std::unique_ptr<detail::ShadowMapImages> images);

  std::unique_ptr<detail::ShadowMapImages> images_;
};

}  // namespace penumbra
