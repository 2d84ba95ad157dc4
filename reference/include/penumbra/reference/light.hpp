// The light and the shadow map's projection (docs/shader-interface.md), in the
// NVIDIA PCSS whitepaper's terms. Light-view space: light centre at the origin, looking
// down +z; the area light is the square x, y in [-L, L] at z = 0.
#pragma once

#include <optional>

namespace penumbra::reference {

struct LightParams {
  double light_world_size = 0.5;           // L: half-width of the square area light
  double frustum_width = 3.75;             // Fw: the light frustum's width at the near plane
  double near_plane = 9.5;                 // n: distance of the near plane from the light
  double bias = 0.0;                       // subtracted from z_r before every comparison
  std::optional<double> filter_radius_uv;  // pcf_poisson's radius in uv; default 2 texels (2 / W)

  // L_uv: the light's size in shadow-map uv (the whitepaper's LIGHT_SIZE_UV).
  double light_size_uv() const { return light_world_size / frustum_width; }

  // pcf_poisson's filter radius for a map `map_width` texels wide.
  double filter_radius(int map_width) const { return filter_radius_uv.value_or(2.0 / map_width); }
};

struct UV {
  double u = 0.0;
  double v = 0.0;
};

// Shadow-map coordinates of the light-view point (x, y, z), z > 0.
inline UV project(const LightParams& light, double x, double y, double z) {
  const double scale = light.near_plane / (z * light.frustum_width);
  return {0.5 + x * scale, 0.5 + y * scale};
}

// The direction (x / z, y / z) of the ray from the light through (u, v):
// the inverse of project() for a given z.
inline UV ray_slope(const LightParams& light, double u, double v) {
  const double scale = light.frustum_width / light.near_plane;
  return {(u - 0.5) * scale, (v - 0.5) * scale};
}

}  // namespace penumbra::reference
