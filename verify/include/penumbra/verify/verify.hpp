// `penumbra verify`: every variant of a built library, each target's own
// shaders executed on a device over the project's test scenes and checked
// against the CPU reference.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "penumbra/compiler/bytecode_frontend.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/support/shard.hpp"
#include "penumbra/verify/function_form.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "penumbra/verify/paths.hpp"
#include "penumbra/verify/progress.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

struct VerifyOptions {
  std::vector<std::string> variants;  // only these (by name); empty = all
  std::vector<Target> targets;        // only these; empty = all the library has
  // Paths whose runs are reported not executed, "not requested" (those with
  // a skip flag, execution_paths(); paths_skipped_by("--no-wine") gives the
  // Direct3D runtimes'); empty = every path runs where it can.
  std::vector<std::string> skipped = {};
  // Only these paths (verify.json's backend names, execution_paths());
  // empty = every path.
  std::vector<std::string> paths = {};
  // The depth image of maps in a hardware encoding (perspective,
  // perspective_reversed) on the paths that read the Vulkan engine's maps
  // and on gl: d24_unorm or d16_unorm as engines store them. Linear maps,
  // hlsl_dx9's R32F map and Wine's runtimes' own maps stay float.
  DepthFormat map_format = DepthFormat::d32_float;
  // vkd3d-compiler for the Direct3D bytecode path, and for the engine's
  // own HLSL around each function form on that path and Wine's; with none
  // (empty compiler), the bytecode path's runs are reported not executed
  // and neither path draws a function form.
  BytecodeTranslator bytecode = {};
  // Only this shard's (variant, target) pairs: the library's i-th variant
  // (from 0) with kAllTargets' j-th target is in shard ((i + j) mod N) + 1.
  Shard shard = {};
  // Threads for the CPU's part (the reference, the checks), the first that
  // drives the devices included; 0 = every core. The results are the same
  // whatever the count.
  int jobs = 0;
  // Told as each (variant, target)'s runs are checked; none: nothing is.
  ProgressConsumer progress = {};
};

// A GPU image against the CPU's next step of screen_blur's chain run on the
// GPU's own previous image: every channel of every pixel, no ambiguity mask.
struct ChainCheck {
  std::size_t values = 0;          // pixels x channels compared
  std::size_t over_tolerance = 0;  // values with |gpu - cpu| > tolerance (or NaN)
  double max_abs_error = 0.0;      // infinity for a NaN
  double tolerance = 0.0;
  bool pass = false;  // values > 0 and over_tolerance == 0
};

// One variant on one scene.
struct SceneRun {
  std::string scene;
  // The query's visibility against the reference (screen_blur: the
  // unblurred shadow factor against the reference factor).
  reference::Comparison comparison;
  double mean_texel_reads = 0.0;  // the query's .y over all pixels (QueryOutput::texel_reads)
  // screen_blur only: the blurred factor against reference::screen_blur of
  // the GPU's factor (reference::kBlurTolerance), and the composite against
  // reference::composite of reference::scene_colour and the GPU's blurred
  // factor (reference::kCompositeTolerance).
  std::optional<ChainCheck> blur;
  std::optional<ChainCheck> composite;
  double seconds = 0.0;  // running and checking this scene

  bool pass() const;  // every check above passed
};

// One variant, one target, one backend ("vulkan", "bytecode" or "gl").
struct TargetRun {
  Target target = Target::spirv;
  std::string backend = "vulkan";
  std::string device;   // the device or driver that ran it
  Execution execution;  // front end and shims
  bool executed = false;
  std::string not_executed;  // why, when not executed
  std::string error;         // why it failed before any comparison (front end, device)
  bool pass = false;         // executed and every scene passed
  std::vector<SceneRun> scenes;
  double seconds = 0.0;  // loading the passes and every scene
};

struct VariantRun {
  std::string name;
  Technique technique = Technique::hard;
  std::vector<TargetRun> runs;
};

// A target's depth pass checked against a CPU ray cast of the scene.
struct DepthCheck {
  std::string scene;
  Target target = Target::spirv;
  std::string backend = "vulkan";  // the path whose map it is (verify.json's backend)
  MapEncoding map_encoding = MapEncoding::linear;   // what the map stores
  DepthFormat map_format = DepthFormat::d32_float;  // in which depth image
  std::size_t texels = 0;  // texels whose centre is clear of every occluder edge
  // Of those, |gpu - ray cast| > 1e-5 relative, plus the z one step of a
  // unorm format spans there.
  std::size_t mismatched = 0;
  double max_abs_error = 0.0;
  bool pass = false;
  double seconds = 0.0;  // rendering and checking the map
};

// A target's min-max mip, built by its own minmax_init and minmax_reduce
// passes on the map its depth pass rendered, against the CPU mip of that map.
struct MinmaxCheck {
  std::string scene;
  Target target = Target::spirv;
  MapEncoding map_encoding = MapEncoding::linear;  // of the map minmax_init decoded
  int levels = 0;                                  // levels the device built
  int expected_levels = 0;                         // N of the CPU mip
  std::size_t texels = 0;                          // nodes compared, every level
  // Of those, min or max not the same float (or a level's size differs).
  std::size_t mismatched = 0;
  std::string error;  // why the mip could not be built or read
  bool pass = false;
  double seconds = 0.0;  // building, reading and checking the mip
};

// The checks of VerifyOptions::shard. A target's depth and min-max mip
// checks belong to the shard of the (variant, target) whose passes the whole
// run would prepare them with; other shards prepare them too but leave them
// out, so that the shards' checks add up to the whole run's.
struct VerifyReport {
  Shard shard;
  DeviceInfo device;
  std::string gl_device;  // empty when the GL path did not run
  std::vector<DepthCheck> depth_checks;
  std::vector<MinmaxCheck> minmax_checks;  // for targets that ran a variant using the mip
  // Each variant's function form per text target on every path that draws
  // it (check_function_form()), and its deferred pass per target on every
  // path that runs the target (check_deferred_mask()).
  std::vector<EngineFormCheck> function_checks;
  std::vector<EngineFormCheck> deferred_checks;
  std::vector<VariantRun> variants;
  std::size_t runs = 0;    // executed (variant, target, backend, scene) runs
  std::size_t failed = 0;  // of those, failed
  double seconds = 0.0;    // the whole verification
  // Every check passed, and some run executed (a shard of many may have none).
  bool pass() const;
};

// Drives every path's devices from one thread per engine, each thread with
// devices of its own (its engine, a GL context, Wine's runtimes): a software
// driver compiles each thread's pipelines on a thread of its own, so on a
// CPU-only machine the compiles overlap. One thread only when
// VerifyOptions::jobs means one. The report is the same whatever the count.
Result<VerifyReport> verify_library(const Library& library, std::span<Engine* const> engines,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics);
// The same on one device thread.
Result<VerifyReport> verify_library(const Library& library, Engine& engine,
                                    const VerifyOptions& options,
                                    const DiagnosticConsumer& diagnostics);

nlohmann::json to_json(const VerifyReport& report, const Library& library);

}  // namespace penumbra
