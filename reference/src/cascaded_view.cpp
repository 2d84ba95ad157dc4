// Each cascade is evaluated only at the pixels that read it, so a view
// costs about one evaluation per pixel (two in the blend bands), not one
// per cascade.
#include "penumbra/reference/cascaded_view.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

std::vector<CascadeMap> cascade_maps(const CascadedStage& stage) {
  std::vector<CascadeMap> maps;
  for (std::size_t c = 0; c < stage.cascades.size(); ++c) {
    Scene scene = cascade_scene(stage, c);
    FloatImage map = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
    maps.push_back({std::move(scene), std::move(map)});
  }
  return maps;
}

std::vector<CascadeMap> sized_as_nearest(const CascadedStage& stage, std::vector<CascadeMap> maps) {
  for (std::size_t c = 0; c < maps.size(); ++c) {
    LightParams& light = maps[c].scene.light;
    const double scale = stage.cascades[c].width / stage.cascades[0].width;
    light.light_world_size *= scale;
    if (light.filter_radius_uv) {
      *light.filter_radius_uv = stage.filter_radius / stage.cascades[0].width;
    }
  }
  return maps;
}

FloatImage cascade_receivers(const StageView& view, const Cascade& cascade) {
  LightParams light;  // the cascade's map, as project() takes it
  light.projection = LightProjection::orthographic;
  light.frustum_width = cascade.width;
  FloatImage out = view.receivers;
  for (std::size_t i = 0; i < view.points.size(); ++i) {
    if (view.surfaces[i] == Surface::none) continue;
    const auto& p = view.points[i];
    const UV uv = project(light, p[0] - cascade.centre_x, p[1] - cascade.centre_y, p[2]);
    out.data[i * 3] = float(uv.u);
    out.data[i * 3 + 1] = float(uv.v);
  }
  return out;
}

Result<CascadedImage> evaluate_cascaded(const Variant& variant, const CascadedStage& stage,
                                        const StageView& view, std::span<const CascadeMap> maps,
                                        const ShaderLimits& limits) {
  const std::vector<double> depths = view_depths(stage.stage, view);
  CascadedImage out{FloatImage(view.receivers.width, view.receivers.height, 1), {}, {}};
  std::vector<std::vector<std::size_t>> pixels(stage.cascades.size());
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const CascadeChoice choice =
        choose_cascade(stage.cascades, stage.view_near, depths[i], stage.blend_band);
    out.choices.push_back(choice);
    if (choice.first >= 0) pixels[std::size_t(choice.first)].push_back(i);
    if (choice.next >= 0) pixels[std::size_t(choice.next)].push_back(i);
  }
  for (std::size_t c = 0; c < stage.cascades.size(); ++c) {
    const FloatImage receivers = cascade_receivers(view, stage.cascades[c]);
    PENUMBRA_TRY_ASSIGN(
        std::vector<FloatImage> images,
        evaluate_visibility(variant, ShadowMapView(maps[c].map), maps[c].scene.light,
                            std::span(&receivers, 1), pixels[c], {}, limits));
    out.cascades.push_back(std::move(images[0]));
  }
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const CascadeChoice& choice = out.choices[i];
    if (choice.first < 0) {
      out.visibility.data[i] = 1.0f;
      continue;
    }
    const double first = out.cascades[std::size_t(choice.first)].data[i];
    const double next = choice.next >= 0 ? out.cascades[std::size_t(choice.next)].data[i] : 0.0;
    out.visibility.data[i] = float(first + (next - first) * choice.next_weight);
  }
  return out;
}

std::vector<SeamFigures> seam_jumps(const CascadedImage& image, const std::vector<bool>& region) {
  std::vector<SeamFigures> seams(image.cascades.empty() ? 0 : image.cascades.size() - 1);
  for (std::size_t i = 0; i < image.choices.size(); ++i) {
    const CascadeChoice& choice = image.choices[i];
    if (choice.next < 0 || !region[i]) continue;
    const double jump = std::abs(image.cascades[std::size_t(choice.first)].data[i] -
                                 image.cascades[std::size_t(choice.next)].data[i]);
    SeamFigures& seam = seams[std::size_t(choice.first)];
    ++seam.pixels;
    seam.mean += jump;
    seam.max = std::max(seam.max, jump);
  }
  for (SeamFigures& seam : seams) {
    if (seam.pixels > 0) seam.mean /= double(seam.pixels);
  }
  return seams;
}

}  // namespace penumbra::reference
