// The light and the shadow map's projection (docs/shader-interface.md), in the
// NVIDIA PCSS whitepaper's terms. Light-view space: light centre at the origin, looking
// down +z; the area light is the square x, y in [-L, L] at z = 0. An
// orthographic map's light is directional: its rays run along +z tilted by
// slopes (s_x, s_y) in [-L, L]^2, a square of directions.
#pragma once

#include <optional>

namespace penumbra {

enum class LightProjection {
  perspective,   // an area light at the origin; u = 0.5 + x n / (z Fw)
  orthographic,  // a directional light; u = 0.5 + x / Fw
};

struct LightParams {
  double light_world_size = 0.5;  // L: the area light's half-width (orthographic: half-slope)
  double frustum_width = 3.75;    // Fw: the frustum's width at n (orthographic: the box's)
  double near_plane = 9.5;        // n: distance of the near plane from the light (from z = 0)
  LightProjection projection = LightProjection::perspective;  // how the map was drawn
  double bias = 0.0;                       // subtracted from z_r before every comparison
  std::optional<double> filter_radius_uv;  // pcf_poisson's radius in uv; default 2 texels (2 / W)

  // L_uv: the light's size in shadow-map uv (the whitepaper's LIGHT_SIZE_UV);
  // orthographic, the uv a penumbra widens by per unit of depth.
  double light_size_uv() const { return light_world_size / frustum_width; }

  bool orthographic() const { return projection == LightProjection::orthographic; }

  // pcf_poisson's filter radius for a map `map_width` texels wide.
  double filter_radius(int map_width) const { return filter_radius_uv.value_or(2.0 / map_width); }

  bool operator==(const LightParams&) const = default;
};

struct UV {
  double u = 0.0;
  double v = 0.0;
};

// Shadow-map coordinates of the light-view point (x, y, z), z > 0.
inline UV project(const LightParams& light, double x, double y, double z) {
  const double scale = light.orthographic() ? 1.0 / light.frustum_width
                                            : light.near_plane / (z * light.frustum_width);
  return {0.5 + x * scale, 0.5 + y * scale};
}

// The ray of map point (u, v): the light-view points (x, y) = origin +
// slope z. A perspective map's rays leave the light's centre; an
// orthographic map's are parallel to z.
struct MapRay {
  UV origin;
  UV slope;
  UV at(double z) const { return {origin.u + slope.u * z, origin.v + slope.v * z}; }
};

// The inverse of project(): the ray along which (u, v) sees.
inline MapRay map_ray(const LightParams& light, double u, double v) {
  if (light.orthographic()) {
    return {{(u - 0.5) * light.frustum_width, (v - 0.5) * light.frustum_width}, {0.0, 0.0}};
  }
  const double scale = light.frustum_width / light.near_plane;
  return {{0.0, 0.0}, {(u - 0.5) * scale, (v - 0.5) * scale}};
}

}  // namespace penumbra
