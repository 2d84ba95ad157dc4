// What verify derives from a scene alone, whatever target or path drew its
// map: the ray cast its maps are held against, and the camera's view of the
// report's stage. One verify asks for each many times (every target's
// maps, every engine-form check); this computes each once, on first use,
// and keeps it for the run.
#pragma once

#include <memory>
#include <tuple>

#include "memo.hpp"
#include "penumbra/reference/stage.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

class SceneTruths {
 public:
  // depth_truth(scene, width, height).
  std::shared_ptr<const DepthTruth> depth(const reference::Scene& scene, int width, int height);
  // reference::view(stage, width, height).
  const reference::StageView& view(const reference::Stage& stage, int width, int height);

 private:
  Memo<std::tuple<reference::Scene, int, int>, std::shared_ptr<const DepthTruth>> depths_;
  Memo<std::tuple<reference::Stage, int, int>, reference::StageView> views_;
};

}  // namespace penumbra
