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
      {PassKind::blur_h, ShaderStage::vertex, "passes/fullscreen.vert", "blur_h", false},
      {PassKind::blur_h, ShaderStage::fragment, "passes/blur_h.frag", "blur_h", true},
      {PassKind::blur_v, ShaderStage::vertex, "passes/fullscreen.vert", "blur_v", false},
      {PassKind::blur_v, ShaderStage::fragment, "passes/blur_v.frag", "blur_v", true},
      {PassKind::composite, ShaderStage::vertex, "passes/fullscreen.vert", "composite", false},
      {PassKind::composite, ShaderStage::fragment, "passes/composite.frag", "composite", false},
  };
  return kPlan;
}

bool runs_pass(PassKind pass, const Variant& variant) {
  switch (pass) {
    case PassKind::depth:
    case PassKind::query:
      return true;
    case PassKind::minmax_init:
    case PassKind::minmax_reduce:
      return uses_minmax_mip(variant.technique);
    case PassKind::blur_h:
    case PassKind::blur_v:
    case PassKind::composite:
      return variant.technique == Technique::screen_blur;
  }
  return false;
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
