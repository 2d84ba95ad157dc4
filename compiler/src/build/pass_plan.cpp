#include "build/pass_plan.hpp"

#include <vector>

#include "penumbra/compiler/targets.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {

std::span<const PassStageSource> pass_plan() {
  static const std::vector<PassStageSource> kPlan = [] {
    std::vector<PassStageSource> plan;
    for (PassKind kind : kAllPassKinds) {
      const PassDescription& pass = describe(kind);
      plan.push_back({kind, ShaderStage::vertex, pass.vertex_source, pass.vertex_file, false});
      plan.push_back(
          {kind, ShaderStage::fragment, pass.fragment_source, to_string(kind), pass.per_variant});
    }
    return plan;
  }();
  return kPlan;
}

std::string output_path(const PassStageSource& source, Target target, const Variant* variant) {
  std::string dir = std::string(to_string(target)) + "/";
  dir += source.per_variant && variant ? variant->name : std::string("common");
  return dir + "/" + output_file_name(target, source.file_stem, source.stage);
}

ShaderJob make_job(const PassStageSource& source, Target target, const Variant* variant) {
  ShaderJob job;
  job.variant = source.per_variant ? variant : nullptr;
  job.target = target;
  job.pass = source.pass;
  job.stage = source.stage;
  job.source_path = std::string(source.source);
  job.output_path = output_path(source, target, variant);
  return job;
}

}  // namespace penumbra
