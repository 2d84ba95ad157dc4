// The edge inputs of docs/robustness.md ("Edge inputs") that the reference
// and the device suites both run: maps with depths 0, inf and NaN, lights
// of size 0 and 1e6 (the largest the CLI takes), and receivers at, before
// and far beyond the near plane, at uv inside and outside [0, 1]. No uv
// lies near a texel boundary of the 16 x 16 maps (ambiguous point samples).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::testing {

struct EdgeMap {
  std::string name;
  FloatImage depth;  // 16 x 16, linear z
};

struct EdgeLight {
  std::string name;
  LightParams light;
};

inline constexpr int kEdgeMapSize = 16;

inline FloatImage uniform_map(float depth) {
  FloatImage map(kEdgeMapSize, kEdgeMapSize, 1);
  for (float& d : map.data) d = depth;
  return map;
}

inline std::vector<EdgeMap> edge_maps() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  // An occluder at 12 in the centre, 20 around it, with rows of 0, inf and NaN.
  FloatImage mixed = uniform_map(20.0f);
  for (int j = 0; j < kEdgeMapSize; ++j) {
    for (int i = 0; i < kEdgeMapSize; ++i) {
      if (i >= 4 && i < 12 && j >= 4 && j < 12) mixed.at(i, j) = 12.0f;
      if (j == 2 || i == 13) mixed.at(i, j) = 0.0f;
      if (j == 9) mixed.at(i, j) = kInf;
      if (i == 6 || j == 14) mixed.at(i, j) = kNaN;
    }
  }
  return {{"mixed", std::move(mixed)}, {"zero", uniform_map(0.0f)}};
}

inline std::vector<EdgeLight> edge_lights() {
  LightParams point;
  point.light_world_size = 0.0;
  LightParams huge;
  huge.light_world_size = 1e6;
  return {{"default", {}}, {"point", point}, {"huge", huge}};
}

// (u, v) pairs: inside the map and outside it on every side.
inline std::vector<std::array<double, 2>> edge_uvs() {
  return {{0.53, 0.41}, {0.37, 0.66}, {-3.01, 0.45}, {4.02, -2.03}, {0.03, 0.97}, {1.52, 1.71}};
}

// Receiver depths: behind the light, just in front of it, before, at and
// just past the near plane, ordinary, and far beyond float range; NaN and
// infinities.
inline std::vector<double> edge_depths(const LightParams& light) {
  const double n = light.near_plane;
  return {std::numeric_limits<double>::quiet_NaN(),
          -std::numeric_limits<double>::infinity(),
          -5.0,
          0.0,
          1e-3,
          n / 2,
          n,
          double(std::nextafter(float(n), 1e9f)),
          15.0,
          1.7e38,
          double(std::numeric_limits<float>::max()),
          std::numeric_limits<double>::infinity()};
}

inline std::vector<reference::Query> edge_queries(const LightParams& light) {
  std::vector<reference::Query> queries;
  for (double z : edge_depths(light)) {
    for (const auto& uv : edge_uvs()) queries.push_back({uv[0], uv[1], z});
  }
  return queries;
}

inline std::string describe(const EdgeMap& map, const EdgeLight& light, const reference::Query& q) {
  std::ostringstream out;
  out << "map " << map.name << ", light " << light.name << ", receiver (" << q.u << ", " << q.v
      << ", " << q.z << ")";
  return out.str();
}

}  // namespace penumbra::testing
