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

// `scene` rendered by `depth`, with `receivers` (u, v, z_r per pixel; the
// scene's receivers_width x receivers_height).
Result<SceneFixture> prepare_scene(Engine& engine, const PassProgram& depth, Target target,
                                   const reference::Scene& scene, FloatImage receivers);

}  // namespace penumbra
