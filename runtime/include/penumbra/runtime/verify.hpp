// `penumbra verify`: every variant of a built library, run on a Vulkan device
// over the project's test scenes and checked against the CPU reference.
#pragma once

#include <nlohmann/json.hpp>

#include "penumbra/compiler/library.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/runtime/engine.hpp"

namespace penumbra {

struct VerifyOptions {
  std::vector<std::string> variants;  // only these (by name); empty = all
};

// One variant on one scene for one target.
struct SceneRun {
  std::string scene;
  reference::Comparison comparison;
};

struct TargetRun {
  Target target = Target::spirv;
  bool executed = false;
  std::string how;    // how the target was executed, or why it was not
  bool pass = false;  // executed and every scene passed
  std::vector<SceneRun> scenes;
};

struct VariantRun {
  std::string name;
  Technique technique = Technique::hard;
  std::vector<TargetRun> targets;
};

// The depth pass checked against a CPU ray cast of the scene.
struct DepthCheck {
  std::string scene;
  std::size_t texels = 0;      // texels away from occluder edges
  std::size_t mismatched = 0;  // of those, |gpu - ray cast| > 1e-5 relative
  double max_abs_error = 0.0;
  bool pass = false;
};

struct VerifyReport {
  DeviceInfo device;
  std::vector<DepthCheck> depth_checks;
  std::vector<VariantRun> variants;
  std::size_t runs = 0;    // executed (variant, target, scene) runs
  std::size_t failed = 0;  // of those, failed
  bool pass() const;
};

Result<VerifyReport> verify_library(const Library& library, Engine& engine,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics);

nlohmann::json to_json(const VerifyReport& report, const Library& library);

}  // namespace penumbra
