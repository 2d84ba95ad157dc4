// The scene both programs draw, in the light's view space
// (docs/shader-interface.md): the light at the origin looking down +z, a
// box standing on the ground, the plane z = kGroundZ.
#pragma once

#include <array>
#include <vector>

namespace scene {

using Vec3 = std::array<float, 3>;

constexpr float kGroundZ = 16.0f;
constexpr Vec3 kBoxMin{0.4f, -0.4f, 13.0f};  // the box's top face is at z = 13
constexpr Vec3 kBoxMax{1.2f, 0.4f, kGroundZ};
constexpr float kGroundHalfWidth = 2.0f;  // the picture shows x, y in [-2, 2]
constexpr int kMapSize = 1024;            // the shadow map, texels per side
constexpr int kImageSize = 512;           // the picture, pixels per side

// The light: the square x, y in [-kLightSize, kLightSize] at z = 0, and the
// shadow map's frustum, kFrustumWidth wide at the near plane kNear, storing
// depths up to kFar.
constexpr float kLightSize = 0.5f;
constexpr float kFrustumWidth = 3.75f;
constexpr float kNear = 9.5f;
constexpr float kFar = 32.0f;

// The box's 12 triangles (both programs draw without culling, so the
// winding does not matter).
inline std::vector<Vec3> box_triangles() {
  // Corner k takes x from bit 0, y from bit 1, z from bit 2: 0 is min, 7 max.
  const auto corner = [](int k) {
    return Vec3{k & 1 ? kBoxMax[0] : kBoxMin[0], k & 2 ? kBoxMax[1] : kBoxMin[1],
                k & 4 ? kBoxMax[2] : kBoxMin[2]};
  };
  constexpr int kFaces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  std::vector<Vec3> triangles;
  for (const auto& f : kFaces) {
    for (int k : {f[0], f[1], f[2], f[0], f[2], f[3]}) triangles.push_back(corner(k));
  }
  return triangles;
}

}  // namespace scene
