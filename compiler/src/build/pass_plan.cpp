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

std::string output_path(const PassStageSource& source, Target target, const Variant* variant,
                        MapEncoding encoding) {
  std::string dir = std::string(to_string(target)) + "/";
  dir += source.per_variant && variant ? variant->name : std::string("common");
  std::string stem(source.file_stem);
  if (!source.per_variant && encoding != MapEncoding::linear) {
    stem += "_" + std::string(to_string(encoding));
  }
  return dir + "/" + output_file_name(target, stem, source.stage);
}

MapEncoding job_encoding(const PassStageSource& source, const Variant& variant) {
  // Of the shared shaders, the depth pass writes the map and minmax_init's
  // fragment shader decodes it; the others never see it.
  const bool sees_map = source.pass == PassKind::depth || (source.pass == PassKind::minmax_init &&
                                                           source.stage == ShaderStage::fragment);
  return source.per_variant || sees_map ? map_encoding(variant.keys) : MapEncoding::linear;
}

ShaderJob make_job(const PassStageSource& source, Target target, const Variant& variant) {
  ShaderJob job;
  job.variant = source.per_variant ? &variant : nullptr;
  job.map_encoding = job_encoding(source, variant);
  job.target = target;
  job.pass = source.pass;
  job.stage = source.stage;
  job.source_path = std::string(source.source);
  job.output_path = output_path(source, target, job.variant, job.map_encoding);
  return job;
}

ShaderJob make_function_job(Target target, const Variant& variant) {
  ShaderJob job;
  job.variant = &variant;
  job.map_encoding = map_encoding(variant.keys);
  job.target = target;
  job.pass = PassKind::query;
  job.stage = ShaderStage::fragment;
  job.form = ShaderForm::function;
  job.source_path = "forms/function.frag";
  job.output_path = std::string(to_string(target)) + "/" + variant.name + "/penumbra_visibility" +
                    (traits(target).is_hlsl ? ".hlsl" : ".glsl");
  return job;
}

}  // namespace penumbra
