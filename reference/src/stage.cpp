// The stage's boxes are placed so that the classic failures show: the
// standing block and the pole cast shadows that harden towards their base
// (contact hardening), the pole's top is near the light (a wide penumbra),
// and the slab hangs over the low block so that occluders at two depths
// overlap in the light's view (a single average blocker depth is wrong).
#include "penumbra/reference/stage.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "penumbra/reference/exact_visibility.hpp"
#include "ray_box.hpp"

namespace penumbra::reference {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 normalized(const Vec3& a) {
  const double length = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / length, a[1] / length, a[2] / length};
}

}  // namespace

CameraFrame camera_frame(const Camera& camera, int width, int height) {
  CameraFrame frame;
  frame.forward = normalized(camera.target - camera.eye);
  frame.right = normalized(cross(frame.forward, {0.0, 0.0, -1.0}));
  frame.up = cross(frame.right, frame.forward);
  frame.half_height = std::tan(camera.vertical_fov_degrees * std::numbers::pi / 360.0);
  frame.half_width = frame.half_height * width / height;
  return frame;
}

Stage report_stage() {
  Stage stage;
  Scene& scene = stage.scene;
  scene.name = "stage";
  scene.light.light_world_size = 0.75;  // wider than the whitepaper's: penumbrae many pixels wide
  scene.light.frustum_width = 6.0;      // the map spans |x| < z / 2 ...
  scene.light.near_plane = 6.0;         // ... so tall boxes stand far from the light's axis
  scene.light.bias = 0.05;              // box tops are in the map they receive from
  scene.boxes = {
      {-3.0, -1.6, -2.2, -0.6, 12.0, 16.0},  // a block standing on the ground
      {2.0, -2.4, 2.4, -2.0, 9.5, 16.0},     // a tall pole
      {0.4, 1.0, 1.8, 2.0, 14.6, 16.0},      // a low block ...
      {-0.6, 0.2, 1.0, 1.4, 11.6, 12.0},     // ... and a slab over it
  };
  scene.plane_z0 = 16.0;
  stage.ground_half_width = 4.2;
  stage.ground_y = {-4.2, 4.2};
  scene.map_width = 512;
  scene.map_height = 512;
  scene.receivers_width = 320;
  scene.receivers_height = 240;
  return stage;
}

StageView view(const Stage& stage, int width, int height) {
  const Scene& scene = stage.scene;
  StageView out{FloatImage(width, height, 3), std::vector<Surface>(std::size_t(width) * height),
                std::vector<Vec3>(std::size_t(width) * height)};
  const Camera& camera = stage.camera;
  const CameraFrame frame = camera_frame(camera, width, height);
  const Vec3 &forward = frame.forward, &right = frame.right, &up = frame.up;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double sx = ((i + 0.5) / width * 2.0 - 1.0) * frame.half_width;
      const double sy = (1.0 - (j + 0.5) / height * 2.0) * frame.half_height;
      const Vec3 d{forward[0] + sx * right[0] + sy * up[0], forward[1] + sx * right[1] + sy * up[1],
                   forward[2] + sx * right[2] + sy * up[2]};
      double nearest = std::numeric_limits<double>::infinity();
      Surface surface = Surface::none;
      if (d[2] > 0.0) {  // the ground plane z = z0 (level: the stage's plane has no slope)
        const double t = (scene.plane_z0 - camera.eye[2]) / d[2];
        const double x = camera.eye[0] + t * d[0], y = camera.eye[1] + t * d[1];
        if (t > 0.0 && std::abs(x) <= stage.ground_half_width && y >= stage.ground_y[0] &&
            y <= stage.ground_y[1]) {
          nearest = t;
          surface = Surface::ground;
        }
      }
      for (const Box& box : scene.boxes) {
        const auto hit = ray_box(box, camera.eye, d);
        if (hit && hit->t > 0.0 && hit->t < nearest) {
          nearest = hit->t;
          surface = hit->axis == 2 && hit->low ? Surface::top : Surface::side;
        }
      }
      const std::size_t index = std::size_t(j) * width + i;
      out.surfaces[index] = surface;
      if (surface == Surface::none) {
        out.receivers.at(i, j, 0) = 0.5f;
        out.receivers.at(i, j, 1) = 0.5f;
        out.receivers.at(i, j, 2) = float(scene.far_z);
        out.points[index] = {0.0, 0.0, scene.far_z};
        continue;
      }
      const Vec3 p{camera.eye[0] + nearest * d[0], camera.eye[1] + nearest * d[1],
                   camera.eye[2] + nearest * d[2]};
      const UV uv = project(scene.light, p[0], p[1], p[2]);
      out.points[index] = p;
      out.receivers.at(i, j, 0) = float(uv.u);
      out.receivers.at(i, j, 1) = float(uv.v);
      out.receivers.at(i, j, 2) = float(p[2]);
    }
  }
  return out;
}

StageView light_view(const Scene& scene, int width, int height) {
  StageView out{receivers(scene, width, height),
                std::vector<Surface>(std::size_t(width) * height, Surface::ground),
                std::vector<Vec3>(std::size_t(width) * height)};
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double z = out.receivers.at(i, j, 2);
      const UV xy =
          map_ray(scene.light, out.receivers.at(i, j, 0), out.receivers.at(i, j, 1)).at(z);
      out.points[std::size_t(j) * width + i] = {xy.u, xy.v, z};
    }
  }
  return out;
}

FloatImage exact_visibility_image(const Scene& scene, const StageView& view) {
  const FloatImage& receivers = view.receivers;
  FloatImage image(receivers.width, receivers.height, 1);
  for (int j = 0; j < receivers.height; ++j) {
    for (int i = 0; i < receivers.width; ++i) {
      const std::size_t index = std::size_t(j) * receivers.width + i;
      const Vec3& p = view.points[index];
      image.at(i, j) = view.surfaces[index] == Surface::none
                           ? 1.0f
                           : float(exact_visibility(scene, p[0], p[1], p[2]));
    }
  }
  return image;
}

}  // namespace penumbra::reference
