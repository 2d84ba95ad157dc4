#include "scene_passes.hpp"

#include <utility>

#include "backend.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra {

std::vector<PassKind> scene_passes(const LibraryVariant& entry, bool builds_mip) {
  std::vector<PassKind> passes;
  for (PassKind pass : runtime::select_passes(describe(entry.variant.technique).passes,
                                              /*draw_depth=*/false, /*deferred=*/false)) {
    const bool minmax = pass == PassKind::minmax_init || pass == PassKind::minmax_reduce;
    if (!minmax || builds_mip) passes.push_back(pass);
  }
  return passes;
}

QueryOutput final_visibility(const runtime::PassOutputs& outputs) {
  const FloatImage* last = nullptr;
  for (const auto& [pass, target] : outputs.targets) {
    if (describe(pass).output.format == TextureFormat::rg32_float) last = &target;
  }
  const FloatImage& first = outputs.targets.front().second;
  return QueryOutput{channel(*last, 0), channel(first, 1), outputs.gpu_ms};
}

SceneOutput scene_output(runtime::PassOutputs outputs) {
  const FloatImage& first = outputs.targets.front().second;
  std::optional<ChainOutput> chain;
  const FloatImage* blurred = outputs.target(PassKind::blur_v);
  FloatImage* composite = nullptr;
  for (auto& [pass, target] : outputs.targets) {
    if (pass == PassKind::composite) composite = &target;
  }
  if (blurred && composite) chain = ChainOutput{channel(*blurred, 0), std::move(*composite)};
  return scene_output(channel(first, 0), channel(first, 1), std::move(chain));
}

}  // namespace penumbra
