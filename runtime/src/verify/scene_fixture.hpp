// A test scene made ready on the device for one target: its shadow map
// rendered by that target's own depth pass, read back as linear z for the
// reference.
#pragma once

#include "penumbra/reference/scene.hpp"
#include "penumbra/runtime/engine.hpp"
#include "penumbra/runtime/library_programs.hpp"
#include "penumbra/runtime/verify.hpp"

namespace penumbra {

struct SceneFixture {
  reference::Scene scene;
  ParamBlock params;
  std::shared_ptr<ShadowMap> map;
  FloatImage normalized_depth;  // the rendered map as stored
  FloatImage linear_depth;      // the same, linear z
  FloatImage receivers;         // (u, v, z_r)
  DepthCheck depth_check;
};

Result<SceneFixture> prepare_scene(Engine& engine, const PassProgram& depth, Target target,
                                   const reference::Scene& scene);

}  // namespace penumbra
