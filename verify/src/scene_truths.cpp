#include "scene_truths.hpp"

namespace penumbra {

std::shared_ptr<const DepthTruth> SceneTruths::depth(const reference::Scene& scene, int width,
                                                     int height) {
  return depths_.get({scene, width, height}, [&] {
    return std::make_shared<const DepthTruth>(depth_truth(scene, width, height));
  });
}

const reference::StageView& SceneTruths::view(const reference::Stage& stage, int width,
                                              int height) {
  return views_.get({stage, width, height}, [&] { return reference::view(stage, width, height); });
}

}  // namespace penumbra
