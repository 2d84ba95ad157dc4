// The report's stage: a ground tile under the square light with boxes on it
// (one standing on the ground, a tall pole, a slab over a low block), seen
// by a camera. Each camera pixel's surface point becomes a receiver, so a
// variant's query shades the picture and exact_visibility() gives its truth.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "penumbra/reference/scene.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

struct Camera {
  std::array<double, 3> eye{0.5, 10.5, 4.5};      // light-view position
  std::array<double, 3> target{0.0, -0.6, 13.6};  // the point at the picture's centre
  double vertical_fov_degrees = 44.0;             // the picture's vertical field of view

  bool operator==(const Camera&) const = default;
};

// The camera's frame for a `width` x `height` picture: pixel (i, j) sees
// along forward + sx right + sy up, where sx = ((i + 0.5) / width * 2 - 1)
// half_width and sy = (1 - (j + 0.5) / height * 2) half_height (row 0 at
// the top). Light-view space has the light looking down +z, so the
// picture's up is towards -z.
struct CameraFrame {
  std::array<double, 3> forward;
  std::array<double, 3> right;
  std::array<double, 3> up;
  double half_width = 0.0;   // tan of half the horizontal field of view
  double half_height = 0.0;  // tan of half the vertical field of view
};

CameraFrame camera_frame(const Camera& camera, int width, int height);

struct Stage {
  Scene scene;                                // the boxes, light and receiver plane (the ground)
  double ground_half_width = 4.2;             // the ground tile: |x| <= this, inside the map ...
  std::array<double, 2> ground_y{-4.2, 4.2};  // ... and y in this range
  Camera camera;

  bool operator==(const Stage&) const = default;
};

// What a camera pixel sees.
enum class Surface : std::uint8_t {
  none,    // nothing: the background
  ground,  // the ground tile
  top,     // a box's face toward the light
  side,    // a box's side, which the light grazes
};

struct StageView {
  // Per pixel, row 0 at the top: (u, v, z_r) of the surface point; a
  // background pixel gets (0.5, 0.5, far_z).
  FloatImage receivers;
  std::vector<Surface> surfaces;              // per pixel
  std::vector<std::array<double, 3>> points;  // per pixel, the light-view surface point
};

// The stage the report pictures (docs/verification.md, "Report").
Stage report_stage();

// The stage as the camera sees it through `width` x `height` pixel centres.
StageView view(const Stage& stage, int width, int height);

// The receiver plane as the light sees it: reference::receivers(scene,
// width, height), every pixel a ground point.
StageView light_view(const Scene& scene, int width, int height);

// exact_visibility() at each pixel's surface point; 1 on the background.
FloatImage exact_visibility_image(const Scene& scene, const StageView& view);

// Whether the light falls on `surface` face-on (ground and tops): the
// pixels whose shadows the report measures.
inline bool receives_light(Surface surface) {
  return surface == Surface::ground || surface == Surface::top;
}

}  // namespace penumbra::reference
