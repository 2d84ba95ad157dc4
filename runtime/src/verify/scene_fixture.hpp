// A test scene made ready on the device: its shadow map rendered by the
// library's own depth pass, read back as linear z for the reference.
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
  FloatImage linear_depth;  // the rendered map, linear z
  FloatImage receivers;     // (u, v, z_r)
  DepthCheck depth_check;
};

Result<SceneFixture> prepare_scene(Engine& engine, const PassProgram& depth,
                                   const reference::Scene& scene);

}  // namespace penumbra
