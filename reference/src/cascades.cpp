// The cascaded stage's boxes stand near the camera, at middle distance and
// far away, at heights that give each cascade penumbrae several of its
// texels wide: a directional light's penumbra is as wide in the world in
// every cascade, so the far ones need tall casters to show one.
#include "penumbra/reference/cascades.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace penumbra::reference {

std::vector<double> practical_splits(double near, double far, int count, double lambda) {
  std::vector<double> splits;
  for (int i = 1; i <= count; ++i) {
    const double f = double(i) / count;
    const double logarithmic = near * std::pow(far / near, f);
    const double uniform = near + (far - near) * f;
    splits.push_back(i == count ? far : lambda * logarithmic + (1.0 - lambda) * uniform);
  }
  return splits;
}

namespace {

using Vec3 = std::array<double, 3>;

// The eight corners of the camera's frustum between view depths d0 and d1.
std::vector<Vec3> slice_corners(const Stage& stage, const CameraFrame& frame, double d0,
                                double d1) {
  std::vector<Vec3> corners;
  const Vec3& eye = stage.camera.eye;
  for (double d : {d0, d1}) {
    for (double sx : {-frame.half_width, frame.half_width}) {
      for (double sy : {-frame.half_height, frame.half_height}) {
        Vec3 c;
        for (int k = 0; k < 3; ++k) {
          c[k] = eye[k] + d * (frame.forward[k] + sx * frame.right[k] + sy * frame.up[k]);
        }
        corners.push_back(c);
      }
    }
  }
  return corners;
}

}  // namespace

std::vector<Cascade> fit_cascades(const Stage& stage, int width, int height, double view_near,
                                  std::span<const double> split_fars, int map_size, double near_z,
                                  double far_z) {
  const CameraFrame frame = camera_frame(stage.camera, width, height);
  std::vector<Cascade> cascades;
  double start = view_near;
  for (double end : split_fars) {
    const std::vector<Vec3> corners = slice_corners(stage, frame, start, end);
    Vec3 centre{0.0, 0.0, 0.0};
    for (const Vec3& c : corners) {
      for (int k = 0; k < 3; ++k) centre[k] += c[k] / double(corners.size());
    }
    double radius = 0.0;
    for (const Vec3& c : corners) {
      radius = std::max(radius, std::hypot(c[0] - centre[0], c[1] - centre[1], c[2] - centre[2]));
    }
    const double side = 2.0 * radius, texel = side / map_size;
    cascades.push_back({std::round(centre[0] / texel) * texel,
                        std::round(centre[1] / texel) * texel, side, near_z, far_z, end});
    start = end;
  }
  return cascades;
}

CascadedStage cascaded_stage() {
  CascadedStage out;
  Stage& stage = out.stage;
  Scene& scene = stage.scene;
  scene.name = "cascaded_stage";
  scene.light.projection = LightProjection::orthographic;
  scene.light.light_world_size = 0.06;  // a sun about 7 degrees across: visible penumbrae
  scene.light.bias = 0.05;              // box tops are in the maps they receive from
  scene.plane_z0 = 40.0;                // the ground, the light 40 units above it
  scene.boxes = {
      // Two long rails crossing every cascade's range: their shadows' edges
      // run through each boundary, one rail low, one high.
      {-8.0, 0.0, -6.5, 88.0, 37.0, 37.4},  {5.0, 0.0, 6.0, 88.0, 32.0, 32.5},
      {-3.0, 2.0, -1.5, 4.0, 38.0, 40.0},    // near the camera: a block ...
      {1.0, 5.0, 3.5, 7.0, 38.5, 38.8},      // ... and a table top over the ground
      {-2.5, 14.0, 0.5, 16.0, 37.0, 40.0},   // middle distance: a block ...
      {1.5, 20.0, 4.0, 24.0, 34.0, 34.5},    // ... a high slab ...
      {-4.0, 30.0, -3.0, 31.0, 28.0, 40.0},  // ... and a pole
      {-5.0, 55.0, -2.0, 60.0, 34.0, 40.0},  // far: a block ...
      {0.0, 66.0, 4.0, 74.0, 30.0, 31.0},    // ... a slab ...
      {-3.0, 80.0, -1.5, 81.5, 24.0, 40.0},  // ... and a tall pole
  };
  // The picture verify draws each cascade's call on; docs/accuracy.md's
  // figures are measured at twice that each way.
  scene.receivers_width = 240;
  scene.receivers_height = 180;
  scene.far_z = 44.0;
  stage.ground_half_width = 30.0;
  // The ground ends before the view depth of 100 where the last cascade
  // (and an engine's camera, verify's too) stops.
  stage.ground_y = {-6.0, 90.0};
  stage.camera = {{0.0, -6.0, 36.0}, {0.0, 25.0, 40.0}, 60.0};  // 4 above the ground
  // The slab's underside and the ground lie inside [near_z, far_z]; the
  // camera's depth to 100 is split more logarithmically than uniformly,
  // as engines default to.
  out.view_near = 1.0;
  out.map_size = 512;
  const std::vector<double> splits = practical_splits(out.view_near, 100.0, 4, 0.75);
  out.cascades = fit_cascades(stage, scene.receivers_width, scene.receivers_height, out.view_near,
                              splits, out.map_size, 20.0, scene.far_z);
  scene.map_width = scene.map_height = out.map_size;
  out.filter_radius = 2.0 * out.cascades[0].width / out.map_size;  // the nearest map's 2 texels
  return out;
}

Scene cascade_scene(const CascadedStage& stage, std::size_t c) {
  const Cascade& cascade = stage.cascades.at(c);
  Scene out = stage.stage.scene;
  const double dx = cascade.centre_x, dy = cascade.centre_y;
  for (Rect& r : out.occluders) r = {r.x0 - dx, r.y0 - dy, r.x1 - dx, r.y1 - dy, r.z};
  for (Box& b : out.boxes) b = {b.x0 - dx, b.y0 - dy, b.x1 - dx, b.y1 - dy, b.z0, b.z1};
  out.plane_z0 += out.plane_dzdx * dx + out.plane_dzdy * dy;
  out.light.projection = LightProjection::orthographic;
  out.light.frustum_width = cascade.width;
  out.light.near_plane = cascade.near_z;
  out.light.filter_radius_uv = stage.filter_radius / cascade.width;
  out.map_width = out.map_height = stage.map_size;
  out.far_z = cascade.far_z;
  return out;
}

Stage cascade_stage(const CascadedStage& stage, std::size_t c) {
  const Cascade& cascade = stage.cascades.at(c);
  Stage out = stage.stage;
  out.scene = cascade_scene(stage, c);
  out.scene.name = "cascaded_stage, cascade " + std::to_string(c);
  for (auto* point : {&out.camera.eye, &out.camera.target}) {
    (*point)[0] -= cascade.centre_x;
    (*point)[1] -= cascade.centre_y;
  }
  // The ground is symmetric in x about the camera's axis, x = 0, where
  // every cascade's centre lies (fit_cascades() of a camera looking along y).
  out.ground_y = {stage.stage.ground_y[0] - cascade.centre_y,
                  stage.stage.ground_y[1] - cascade.centre_y};
  return out;
}

CascadeChoice choose_cascade(std::span<const Cascade> cascades, double view_near, double depth,
                             double blend_band) {
  double start = view_near;
  for (std::size_t c = 0; c < cascades.size(); ++c) {
    const double end = cascades[c].split_far;
    if (depth <= end) {
      CascadeChoice choice{int(c), -1, 0.0};
      const double band = blend_band * (end - start);
      if (c + 1 < cascades.size() && band > 0.0 && depth > end - band) {
        choice.next = int(c + 1);
        choice.next_weight = (depth - (end - band)) / band;
      }
      return choice;
    }
    start = end;
  }
  return {};
}

std::vector<double> view_depths(const Stage& stage, const StageView& view) {
  const CameraFrame frame = camera_frame(stage.camera, view.receivers.width, view.receivers.height);
  std::vector<double> depths(view.points.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < depths.size(); ++i) {
    if (view.surfaces[i] == Surface::none) continue;
    const auto& p = view.points[i];
    double d = 0.0;
    for (int k = 0; k < 3; ++k) d += (p[k] - stage.camera.eye[k]) * frame.forward[k];
    depths[i] = d;
  }
  return depths;
}

}  // namespace penumbra::reference
