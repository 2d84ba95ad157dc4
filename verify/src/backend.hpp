// One execution path of verify: an engine that runs a variant's passes for
// a target on the prepared scenes. verify_library() checks what every
// backend returns against the CPU reference, the same way for each; adding
// a path is one new backend file and one line in verify_library.cpp.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine_shaders.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"
#include "penumbra/verify/function_form.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "scene_fixture.hpp"
#include "scene_passes.hpp"

namespace penumbra {

// screen_blur's images after the factor, each the receivers' size.
struct ChainOutput {
  FloatImage blurred;    // blur_v's .x, one channel: the blurred factor
  FloatImage composite;  // the composite pass's RGBA over the fixture's colour
};

// What a variant's passes wrote on one scene.
struct SceneOutput {
  FloatImage visibility;             // the query's .x (screen_blur: the unblurred factor)
  FloatImage texel_reads;            // the query's .y (docs/shader-interface.md)
  std::optional<ChainOutput> chain;  // screen_blur only
  // A path that draws the scene's map with the target's depth pass itself:
  // that map as stored and as linear z, which the reference then reads
  // instead of the fixture's, and, on the run that drew it, its check
  // against the ray cast.
  std::shared_ptr<const FloatImage> own_stored_depth;
  std::shared_ptr<const FloatImage> own_linear_depth;
  std::optional<DepthCheck> own_depth_check;
};

// What a path's passes wrote, on the scene's own map: the query's (or the
// deferred pass's) two channels, and screen_blur's `chain`.
inline SceneOutput scene_output(FloatImage visibility, FloatImage texel_reads,
                                std::optional<ChainOutput> chain = std::nullopt) {
  SceneOutput out;
  out.visibility = std::move(visibility);
  out.texel_reads = std::move(texel_reads);
  out.chain = std::move(chain);
  return out;
}

// What the passes wrote, from their targets: the first screen pass's .x and
// .y (the visibility, or the factor a blur then filters, and the texel
// reads), and where they ran blur_v and the composite, the chain.
SceneOutput scene_output(runtime::PassOutputs outputs);

// An engine's own draw of the report's stage around a function form
// (function_form.cpp): the variant, the engine's camera and the light's
// view-projection, the function form's text and its reflection with the
// engine's vertex input, render target and depth buffer, and the stage's
// triangles in light-view space. Each backend writes the engine's stages
// for its compiler (engine_shaders.hpp).
struct SurfaceDraw {
  const Library* library = nullptr;
  const LibraryVariant* entry = nullptr;
  Target target = Target::glsl450;
  std::string where;  // the function form's file, in errors
  Matrix4 camera{};
  Matrix4 light{};
  LightClipDepth light_depth;     // how the light's clip position gives z_r
  VertexOptions vertex;           // the picture's size, and whether the function takes the pixel
  std::string function_text;      // the function form, which the fragment stage pastes
  std::optional<CallLight> call;  // what an atlas variant's function takes at each call
  ParamBlock params;              // the surface draw's block (the fixture's, less `call`'s)
  PassReflection reflection;      // what the engine binds by
  std::vector<std::array<float, 3>> triangles;
  int width = 0;
  int height = 0;
};

// An engine's deferred pass over its camera's depth of the report's stage
// (deferred_mask.cpp): the variant, its pass's files, the camera's depth
// buffer as stored (one channel, the picture's size, row 0 first) and the
// parameters with the pass's matrices.
struct DeferredDraw {
  const Library* library = nullptr;
  const LibraryVariant* entry = nullptr;
  Target target = Target::glsl450;
  FloatImage camera_depth;
  ParamBlock params;
};

// What a backend drew: (x, y, visibility, w) per pixel, row 0 first, and
// the map it drew itself where it does not read the scene's (Wine's
// runtimes draw their own), as stored.
struct SurfacePicture {
  FloatImage clip;
  std::shared_ptr<const FloatImage> own_stored_depth;
};

// A variant's passes for one target, loaded by a backend.
struct LoadedPasses {
  Execution execution;  // how the target's files reach the device (verify.json)
  // The passes on one scene of the target: a failed run when it errs.
  std::function<Result<SceneOutput>(const SceneFixture&)> run;
};

class Backend {
 public:
  virtual ~Backend() = default;

  // TargetRun::backend in verify.json: "vulkan", "gl".
  virtual std::string name() const = 0;
  // The device or driver that runs the passes; empty when missing().
  virtual std::string device() const = 0;
  // Why this path cannot run here (no driver, not built, not requested);
  // empty when it can. Its runs are then reported not executed, with this.
  virtual std::string missing() const = 0;
  // Whether this path runs `target`'s files (others are no text of its API).
  virtual bool executes(Target target) const = 0;
  // Why this path cannot run `entry`'s files for `target` here although it
  // runs the target (the library lacks them); empty when it can. That run is
  // then reported not executed, with this.
  virtual std::string not_executed(const LibraryVariant& /*entry*/, Target /*target*/) const {
    return {};
  }
  // Runs of `target` on this path follow soon: a path whose device takes
  // seconds to start begins starting it now, without waiting, so that it
  // boots while the other paths draw (Wine's runtimes). Its errors show
  // at load().
  virtual void expect(Target /*target*/) {}
  // `entry`'s passes for `target` (its query and the passes the query needs,
  // or screen_blur's chain), ready to run on each of `scenes`. An error
  // (a file, a front end, a mip the scenes lack) fails the run.
  virtual Result<LoadedPasses> load(const Library& library, const LibraryVariant& entry,
                                    Target target, const TargetScenes& scenes) = 0;

  // Whether this path draws an engine's own geometry around `target`'s
  // function form (draw_surface).
  virtual bool draws_surfaces(Target /*target*/) const { return false; }
  // `draw` on `fixture`'s map, or on one of its own; `execution` says how
  // the stages reached the device.
  virtual Result<SurfacePicture> draw_surface(const SurfaceDraw& draw,
                                              const SceneFixture& /*fixture*/,
                                              Execution& /*execution*/) {
    return make_error(Error::Kind::internal, draw.where,
                      "the " + name() + " path draws no surfaces");
  }

  // `draw`'s deferred pass on `fixture`'s map, or on one of its own, as
  // the query of the picture: on every target this path executes.
  virtual Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& fixture,
                                           Execution& execution) = 0;
};

class CameraStages;       // camera_stage.hpp
class PictureReferences;  // penumbra/verify/stage_picture.hpp

// `entry`'s function form for `target` drawn on `backend`, the scene's map
// drawn on `engine` by the target's depth pass, from `stages`, judged
// against a reference from `references` (function_form.cpp): on the
// report's stage, or with `cascade` on the cascaded stage, called for that
// cascade.
Result<EngineFormCheck> check_function_form(Engine& engine, Backend& backend, CameraStages& stages,
                                            PictureReferences& references, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            std::optional<int> cascade);

// `entry`'s query (or screen_blur's four passes), each loaded by `load`,
// run on `engine` over the maps (and min-max mips) the scenes hold: the
// paths that execute on the Vulkan engine (vulkan_backend.cpp).
Result<LoadedPasses> load_on_engine(Engine& engine, const LibraryVariant& entry,
                                    const TargetScenes& scenes, const PassLoader& load);

// `entry`'s deferred pass for `target` run on `backend`, the scene's map
// drawn on `engine` by the target's depth pass, from `stages`, judged
// against a reference from `references` (deferred_mask.cpp); `cascade` as
// check_function_form()'s.
Result<EngineFormCheck> check_deferred_mask(Engine& engine, Backend& backend, CameraStages& stages,
                                            PictureReferences& references, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            std::optional<int> cascade);

// `draw` on `engine` over `fixture`'s map with `program`, the deferred pass
// loaded for the Vulkan engine (the paths that run on it). A technique that
// reads the min-max mip gets it built on the map first by the target's own
// build passes, as an engine would.
Result<SceneOutput> deferred_on_engine(Engine& engine, const DeferredDraw& draw,
                                       const SceneFixture& fixture, const PassProgram& program);

// One of the engine's stages of `draw` (its text, and a name for errors)
// compiled for the Vulkan engine: by the target's glslang front end, or to
// bytecode and translated.
using SurfaceStageCompiler = std::function<Result<StageCode>(
    ShaderStage stage, const std::string& text, const std::string& name)>;

// `draw` on `engine` over `fixture`'s map (and its min-max mip, built as
// for deferred_on_engine): `program`'s viewport and depth conventions, its
// stages from `compile` (the paths that draw on the Vulkan engine,
// vulkan_backend.cpp).
Result<SurfacePicture> surface_on_engine(Engine& engine, const SurfaceDraw& draw,
                                         const SceneFixture& fixture, PassProgram program,
                                         const SurfaceStageCompiler& compile);

// `translator` with a memo of its own where it has none: the backends of
// one verify or report, on every device thread, then run vkd3d-compiler
// once per distinct input.
BytecodeTranslator shared_runs(BytecodeTranslator translator);

// Every path's backend, in report order (the table in paths.cpp): the
// bytecode paths through `bytecode`, each of `skipped` (paths with a skip
// flag) reporting its runs not executed. A new path is a new backend file
// and a row there.
std::vector<std::unique_ptr<Backend>> all_backends(Engine& engine,
                                                   const BytecodeTranslator& bytecode,
                                                   const std::vector<std::string>& skipped);

// Every target on the Vulkan engine, on the maps (and min-max mips) the
// scenes hold (vulkan_backend.cpp).
std::unique_ptr<Backend> vulkan_backend(Engine& engine);

// Why `entry` cannot run as `target`'s Direct3D bytecode (the library was
// built without an HLSL compiler), or empty: the bytecode paths' not_executed().
std::string lacking_bytecode(const LibraryVariant& entry, Target target);

// The Direct3D targets' bytecode translated to SPIR-V by vkd3d-compiler
// (`translator`), as Proton runs it, on the Vulkan engine like
// vulkan_backend (bytecode_backend.cpp). No translator reports every run
// not executed.
std::unique_ptr<Backend> bytecode_backend(Engine& engine, BytecodeTranslator translator);

// glsl330 and glsl450 through the OpenGL driver (penumbra::gl), on the
// scenes' normalized depth (gl_backend.cpp). `device` selects the GL device
// like GlEngineOptions; a `not_requested` reason reports every run not
// executed with it.
std::unique_ptr<Backend> gl_backend(const std::string& not_requested, const std::string& device);

enum class D3dRuntime;  // penumbra/d3d/engine.hpp

// The Direct3D targets' bytecode on a real Direct3D runtime, Wine's under
// Xvfb (penumbra::d3d): hlsl_dx9 on d3d9, hlsl_dx10 on d3d10, hlsl_dx11 on
// d3d11. The runtimes' backends alive at once share one Wine session,
// started on first use (wine_backend.cpp). Each draws every scene's map
// with the target's own depth pass and runs the queries on it. A
// `not_requested` reason reports every run not executed with it.
// With `compiler`, each also draws the function form inside an engine's own
// HLSL, compiled to bytecode by its vkd3d-compiler.
std::unique_ptr<Backend> wine_backend(D3dRuntime runtime, const std::string& not_requested,
                                      BytecodeTranslator compiler);

}  // namespace penumbra
