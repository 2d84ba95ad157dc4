#include "build/pass_plan.hpp"

#include "penumbra/compiler/targets.hpp"

namespace penumbra {

std::span<const PassStageSource> pass_plan() {
  static constexpr PassStageSource kPlan[] = {
      {PassKind::depth, ShaderStage::vertex, "passes/depth.vert", "depth", false},
      {PassKind::depth, ShaderStage::fragment, "passes/depth.frag", "depth", false},
      {PassKind::minmax_init, ShaderStage::vertex, "passes/fullscreen.vert", "minmax_init", false},
      {PassKind::minmax_init, ShaderStage::fragment, "passes/minmax_init.frag", "minmax_init",
       false},
      {PassKind::minmax_reduce, ShaderStage::vertex, "passes/fullscreen.vert", "minmax_reduce",
       false},
      {PassKind::minmax_reduce, ShaderStage::fragment, "passes/minmax_reduce.frag", "minmax_reduce",
       false},
      {PassKind::query, ShaderStage::vertex, "passes/fullscreen.vert", "fullscreen", false},
      {PassKind::query, ShaderStage::fragment, "passes/query.frag", "query", true},
  };
  return kPlan;
}

bool runs_pass(PassKind pass, const Variant& variant) {
  const bool minmax = pass == PassKind::minmax_init || pass == PassKind::minmax_reduce;
  return !minmax || uses_minmax_mip(variant.technique);
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
