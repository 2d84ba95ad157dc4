#include "penumbra/reference/precision.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra {
namespace {

nlohmann::json depth_json(const DepthCheck& c) {
  nlohmann::json out = {{"scene", c.scene},
                        {"target", to_string(c.target)},
                        {"backend", c.backend},
                        {"texels_checked", c.texels},
                        {"mismatched", c.mismatched},
                        {"max_abs_error", c.max_abs_error},
                        {"pass", c.pass}};
  // Linear maps, the library's own, are every check that has no encoding.
  if (c.map_encoding != MapEncoding::linear) out["map_encoding"] = to_string(c.map_encoding);
  if (c.map_format != DepthFormat::d32_float) out["map_format"] = to_string(c.map_format);
  return out;
}

nlohmann::json minmax_json(const MinmaxCheck& c) {
  nlohmann::json out = {{"scene", c.scene},
                        {"target", to_string(c.target)},
                        {"levels", c.levels},
                        {"expected_levels", c.expected_levels},
                        {"texels_checked", c.texels},
                        {"mismatched", c.mismatched},
                        {"pass", c.pass}};
  if (c.map_encoding != MapEncoding::linear) out["map_encoding"] = to_string(c.map_encoding);
  if (!c.error.empty()) out["error"] = c.error;
  return out;
}

nlohmann::json function_json(const EngineFormCheck& c) {
  nlohmann::json out = {{"variant", c.variant},
                        {"target", to_string(c.target)},
                        {"backend", c.backend},
                        {"front_end", c.execution.front_end},
                        {"shims", c.execution.shims},
                        {"surface_pixels", c.surface_pixels},
                        {"compared", c.comparison.compared},
                        {"ambiguous", c.comparison.ambiguous},
                        {"over_tolerance", c.comparison.over_tolerance},
                        {"max_abs_error", c.comparison.max_abs_error},
                        {"mean_abs_error", c.comparison.mean_abs_error},
                        {"tolerance", c.comparison.tolerance},
                        {"camera_agreement", c.camera_agreement},
                        {"pass", c.pass}};
  // Float maps are every check that names no format.
  if (c.map_format != DepthFormat::d32_float) out["map_format"] = to_string(c.map_format);
  // The report's stage is every check that names no cascade.
  if (c.cascade) out["cascade"] = *c.cascade;
  if (!c.error.empty()) out["error"] = c.error;
  return out;
}

nlohmann::json chain_json(const ChainCheck& c) {
  return {{"values", c.values},
          {"over_tolerance", c.over_tolerance},
          {"max_abs_error", c.max_abs_error},
          {"tolerance", c.tolerance},
          {"pass", c.pass}};
}

// A query's comparison at the top level; screen_blur's three checks under
// factor, blur and composite, with the scene's pass for all three.
nlohmann::json scene_json(const SceneRun& s) {
  nlohmann::json entry;
  if (s.blur && s.composite) {
    entry["factor"] = s.comparison;
    entry["blur"] = chain_json(*s.blur);
    entry["composite"] = chain_json(*s.composite);
    entry["pass"] = s.pass();
  } else {
    entry = s.comparison;
  }
  entry["scene"] = s.scene;
  entry["mean_texel_reads"] = s.mean_texel_reads;
  return entry;
}

nlohmann::json run_json(const TargetRun& run) {
  nlohmann::json out = {
      {"target", to_string(run.target)}, {"backend", run.backend}, {"executed", run.executed}};
  if (!run.executed) {
    out["not_executed"] = run.not_executed;
    return out;
  }
  out["device"] = run.device;
  out["front_end"] = run.execution.front_end;
  out["shims"] = run.execution.shims;
  out["pass"] = run.pass && run.error.empty();
  if (!run.error.empty()) out["error"] = run.error;
  nlohmann::json scenes = nlohmann::json::array();
  for (const SceneRun& s : run.scenes) scenes.push_back(scene_json(s));
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
                        {"gl_device", report.gl_device},
                        {"tolerances", tolerances},
                        {"max_ambiguous_fraction", reference::kMaxAmbiguousFraction},
                        {"shard", to_string(report.shard)},
                        {"pass", report.pass()},
                        {"runs", report.runs},
                        {"failed", report.failed}};
  nlohmann::json depth = nlohmann::json::array();
  for (const DepthCheck& c : report.depth_checks) depth.push_back(depth_json(c));
  out["depth_pass"] = depth;
  nlohmann::json minmax = nlohmann::json::array();
  for (const MinmaxCheck& c : report.minmax_checks) minmax.push_back(minmax_json(c));
  out["minmax_mip"] = minmax;
  nlohmann::json function = nlohmann::json::array();
  for (const EngineFormCheck& c : report.function_checks) function.push_back(function_json(c));
  out["function_form"] = function;
  nlohmann::json deferred = nlohmann::json::array();
  for (const EngineFormCheck& c : report.deferred_checks) deferred.push_back(function_json(c));
  out["deferred_mask"] = deferred;
  nlohmann::json variants = nlohmann::json::array();
  for (const VariantRun& v : report.variants) {
    nlohmann::json runs = nlohmann::json::array();
    for (const TargetRun& run : v.runs) runs.push_back(run_json(run));
    variants.push_back({{"name", v.name}, {"technique", to_string(v.technique)}, {"runs", runs}});
  }
  out["variants"] = variants;
  return out;
}

}  // namespace penumbra
