// A test scene made ready on the Vulkan engine for one target: its shadow
// map rendered by that target's own depth pass, read back as linear z for
// the reference. Every backend runs on these: the Vulkan one on the map
// itself, the others on its normalized depth.
#pragma once

#include <optional>
#include <vector>

#include "penumbra/reference/scene.hpp"
#include "penumbra/verify/verify.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

struct SceneFixture {
  reference::Scene scene;
  ParamBlock params;
  std::shared_ptr<ShadowMap> map;
  FloatImage normalized_depth;  // the rendered map as stored
  FloatImage linear_depth;      // the same, linear z
  FloatImage receivers;         // (u, v, z_r)
  FloatImage colour;            // what screen_blur's composite draws over (reference::scene_colour)
  DepthCheck depth_check;
};

// Every scene of one target.
struct TargetScenes {
  std::vector<SceneFixture> scenes;
  // Whether the maps hold the min-max mip the target's own passes built, or
  // why they could not; absent until a variant that reads the mip asks.
  std::optional<Status> minmax;
};

// `linear` (a map of `scene` drawn by `target`'s depth pass, as linear z)
// against a ray cast at each texel's centre: every texel whose centre lies
// clear of an occluder's edge must hold the ray cast's surface, so a map
// shifted by a texel row fails. `backend` is the path that drew it.
DepthCheck check_depth(const reference::Scene& scene, Target target, const FloatImage& linear,
                       const std::string& backend);

// `scene` rendered by `depth`, with `receivers` (u, v, z_r per pixel; the
// scene's receivers_width x receivers_height).
Result<SceneFixture> prepare_scene(Engine& engine, const PassProgram& depth, Target target,
                                   const reference::Scene& scene, FloatImage receivers);

}  // namespace penumbra
