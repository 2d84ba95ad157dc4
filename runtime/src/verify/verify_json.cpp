#include "penumbra/reference/precision.hpp"
#include "penumbra/runtime/verify.hpp"

namespace penumbra {
namespace {

nlohmann::json depth_json(const DepthCheck& c) {
  return {{"scene", c.scene},
          {"texels_checked", c.texels},
          {"mismatched", c.mismatched},
          {"max_abs_error", c.max_abs_error},
          {"pass", c.pass}};
}

nlohmann::json target_json(const TargetRun& run) {
  nlohmann::json out = {{"executed", run.executed}, {"how", run.how}};
  if (!run.executed) return out;
  out["pass"] = run.pass;
  nlohmann::json scenes = nlohmann::json::array();
  for (const SceneRun& s : run.scenes) {
    nlohmann::json entry = s.comparison;
    entry["scene"] = s.scene;
    scenes.push_back(entry);
  }
  out["scenes"] = scenes;
  return out;
}

}  // namespace

nlohmann::json to_json(const VerifyReport& report, const Library& library) {
  const reference::SamplingPrecision precision{
      static_cast<int>(std::max(1u, report.device.sub_texel_precision_bits))};
  nlohmann::json tolerances = nlohmann::json::object();
  for (Technique t : kAllTechniques) {
    tolerances[std::string(to_string(t))] = reference::tolerance(t, precision);
  }
  nlohmann::json out = {{"generator", library.generator},
                        {"device",
                         {{"name", report.device.name},
                          {"driver", report.device.driver},
                          {"sub_texel_precision_bits", report.device.sub_texel_precision_bits}}},
                        {"tolerances", tolerances},
                        {"max_ambiguous_fraction", reference::kMaxAmbiguousFraction},
                        {"pass", report.pass()},
                        {"runs", report.runs},
                        {"failed", report.failed}};
  nlohmann::json depth = nlohmann::json::array();
  for (const DepthCheck& c : report.depth_checks) depth.push_back(depth_json(c));
  out["depth_pass"] = depth;
  nlohmann::json variants = nlohmann::json::array();
  for (const VariantRun& v : report.variants) {
    nlohmann::json targets = nlohmann::json::object();
    for (const TargetRun& run : v.targets) {
      targets[std::string(to_string(run.target))] = target_json(run);
    }
    variants.push_back(
        {{"name", v.name}, {"technique", to_string(v.technique)}, {"targets", targets}});
  }
  out["variants"] = variants;
  return out;
}

}  // namespace penumbra
