// One testcase per check, named so that the same check has the same name in
// every shard and in the whole run: merging shards and comparing runs is
// then a matter of names.
#include "verify_junit.hpp"

#include <sstream>

namespace penumbra::cli {
namespace {

using Outcome = JunitCase::Outcome;

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

JunitCase make_case(std::string classname, std::string name, double seconds, bool pass,
                    std::string message) {
  JunitCase c{std::move(classname), std::move(name), seconds, Outcome::passed, "", ""};
  if (!pass) {
    c.outcome = Outcome::failed;
    c.message = std::move(message);
  }
  return c;
}

// A multi-line error (a compiler's log): its first line as the message, all
// of it as the details.
void fail_with(JunitCase& c, const std::string& error) {
  c.outcome = Outcome::failed;
  c.message = error.substr(0, error.find('\n'));
  if (c.message.size() != error.size()) c.details = error;
}

std::string comparison_failure(const std::string& what, const reference::Comparison& c) {
  return what + ": " + std::to_string(c.over_tolerance) + " of " + std::to_string(c.compared) +
         " pixels over the tolerance " + number(c.tolerance) + " (max error " +
         number(c.max_abs_error) + "), " + std::to_string(c.ambiguous) + " of " +
         std::to_string(c.pixels) + " ambiguous";
}

std::string chain_failure(const std::string& what, const ChainCheck& c) {
  return what + ": " + std::to_string(c.over_tolerance) + " of " + std::to_string(c.values) +
         " values over the tolerance " + number(c.tolerance) + " (max error " +
         number(c.max_abs_error) + ")";
}

// Each failed part of the scene's check, "; " between them.
std::string scene_failure(const SceneRun& s) {
  std::string message;
  const auto add = [&message](const std::string& part) {
    message += (message.empty() ? "" : "; ") + part;
  };
  if (!s.comparison.pass) add(comparison_failure(s.blur ? "factor" : "visibility", s.comparison));
  if (s.blur && !s.blur->pass) add(chain_failure("blur", *s.blur));
  if (s.composite && !s.composite->pass) add(chain_failure("composite", *s.composite));
  return message;
}

// A per-target check's scene, after the map encoding it ran on where that
// is an engine's ("perspective/steps"): each encoding has its own maps.
std::string encoded_scene(MapEncoding encoding, const std::string& scene) {
  return encoding == MapEncoding::linear ? scene : std::string(to_string(encoding)) + "/" + scene;
}

void add_runs(JunitSuite& suite, const VariantRun& v) {
  for (const TargetRun& t : v.runs) {
    const std::string path = std::string(to_string(t.target)) + "/" + t.backend;
    if (!t.executed) {
      suite.cases.push_back({v.name, path, t.seconds, Outcome::skipped, t.not_executed, ""});
      continue;
    }
    if (!t.error.empty()) {
      JunitCase c{v.name, path, t.seconds, Outcome::passed, "", ""};
      fail_with(c, t.error);
      suite.cases.push_back(std::move(c));
      continue;
    }
    for (const SceneRun& s : t.scenes) {
      suite.cases.push_back(
          make_case(v.name, path + "/" + s.scene, s.seconds, s.pass(), scene_failure(s)));
    }
  }
}

}  // namespace

JunitReport to_junit(const VerifyReport& report) {
  JunitSuite suite;
  suite.name = "penumbra verify";
  if (report.shard.count > 1) suite.name += " shard " + to_string(report.shard);
  suite.properties = {{std::string(kJunitShardProperty), to_string(report.shard)},
                      {"penumbra.device", report.device.name}};
  suite.seconds = report.seconds;
  for (const DepthCheck& c : report.depth_checks) {
    suite.cases.push_back(make_case(
        "depth_pass",
        std::string(to_string(c.target)) + (c.backend == "vulkan" ? "" : "@" + c.backend) + "/" +
            encoded_scene(c.map_encoding, c.scene),
        c.seconds, c.pass,
        std::to_string(c.mismatched) + " of " + std::to_string(c.texels) +
            " texels off the ray cast (max error " + number(c.max_abs_error) + ")"));
  }
  for (const MinmaxCheck& c : report.minmax_checks) {
    JunitCase check = make_case(
        "minmax_mip",
        std::string(to_string(c.target)) + "/" + encoded_scene(c.map_encoding, c.scene), c.seconds,
        c.pass,
        std::to_string(c.mismatched) + " of " + std::to_string(c.texels) + " nodes off, " +
            std::to_string(c.levels) + " of " + std::to_string(c.expected_levels) + " levels");
    if (!c.error.empty()) fail_with(check, c.error);
    suite.cases.push_back(std::move(check));
  }
  for (const auto& [form, checks] : {std::pair{"function_form", &report.function_checks},
                                     std::pair{"deferred_mask", &report.deferred_checks}}) {
    for (const EngineFormCheck& c : *checks) {
      JunitCase check = make_case(
          form,
          c.variant + "/" + std::string(to_string(c.target)) + "/" + c.backend +
              (c.cascade ? "/cascade" + std::to_string(*c.cascade) : ""),
          c.seconds, c.pass,
          std::to_string(c.comparison.over_tolerance) + " of " +
              std::to_string(c.comparison.compared) + " pixels over the tolerance (max error " +
              number(c.comparison.max_abs_error) + "), camera agreement " +
              number(c.camera_agreement));
      if (!c.error.empty()) fail_with(check, c.error);
      suite.cases.push_back(std::move(check));
    }
  }
  for (const VariantRun& v : report.variants) add_runs(suite, v);
  return {"penumbra verify", {std::move(suite)}};
}

}  // namespace penumbra::cli
