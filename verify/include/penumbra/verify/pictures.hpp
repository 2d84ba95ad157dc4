// Every variant's shaders run on one caller-given scene and view (the
// report's stage), each target on each execution path as `penumbra verify`
// runs them, and handed one run at a time to a sink with the CPU reference
// of the same image.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "penumbra/reference/scene.hpp"
#include "penumbra/verify/progress.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra {

struct PictureOptions {
  std::vector<std::string> variants;  // only these (by name); empty = all
  std::vector<Target> targets;        // only these; empty = all the library has
  std::vector<std::string> skipped;   // paths not run, as VerifyOptions::skipped
  BytecodeTranslator bytecode = {};   // the Direct3D bytecode path; none: not executed
  int timed_runs = 3;                 // runs of the passes timed; the fastest is reported
  int jobs = 0;  // threads for the references and the sink, this one included; 0: every core
  ProgressConsumer progress = {};  // told as each run is handed to the sink; none: nothing is
};

// Why a scene under the report's spot light cannot show `variant`, or
// empty: an orthographic map needs a directional light.
std::string off_stage(const Variant& variant);

// A scene and the receivers to shade it at (u, v, z_r per pixel, the
// scene's receivers_width x receivers_height).
struct PictureScene {
  reference::Scene scene;
  FloatImage receivers;
};

// One variant on one target and path.
struct PictureRun {
  std::size_t order = 0;  // its place among the runs, in library order, from 0
  std::string variant;
  Technique technique = Technique::hard;
  Target target = Target::spirv;
  std::string backend;       // "vulkan", "bytecode", "gl", "d3d9", ... as in verify.json
  std::string device;        // the device or driver that ran it
  Execution execution;       // front end and shims
  std::string not_executed;  // why the path could not run it here; then no images
  std::string error;         // why it failed (front end, device); then no images
  // What the variant shows: the query's visibility (screen_blur: the
  // blurred factor), 1 channel, and the CPU reference of the same image.
  FloatImage visibility;
  FloatImage reference;
  // 1 where the reference leaves the pixel undecided (verify's "ambiguous":
  // its value depends on choices a GPU may make), else 0; screen_blur: none.
  FloatImage reference_ambiguous;
  FloatImage texel_reads;    // the query's per-pixel texel reads
  double run_seconds = 0.0;  // the fastest timed run of the passes, read-back included
};

// Called from several threads at once (PictureOptions::jobs), in no set
// order: PictureRun::order says where each run belongs.
using PictureSink = std::function<Status(PictureRun&&)>;

// Runs every wanted (variant, target, path) on `scene`, the device's part
// in library order on this thread, and gives each to `sink` with its
// reference, computed on the CPU workers meanwhile. After an error the sink
// returns, no more runs start; the error of the earliest run is returned.
// Errors: bad_input for a variant the library lacks; a depth pass or
// min-max mip that cannot be built fails the runs of its target, not the call.
Status render_pictures(const Library& library, Engine& engine, const PictureScene& scene,
                       const PictureOptions& options, const PictureSink& sink,
                       const DiagnosticConsumer& diagnostics);

}  // namespace penumbra
