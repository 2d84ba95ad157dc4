// GlEngine: runs a variant's passes as GLSL text (glsl330 or glsl450 as
// emitted) on an OpenGL 4.5 core context over headless EGL, normally Mesa's
// llvmpipe (docs/gl.md). Every pass is bound by its reflection, index.json's
// `reflection.<pass>.<target>`, as a GL engine that drops the library in
// does: the query (after the shadow map's min-max mip when the query reads
// it), a variant's whole pass list (run_passes: a chain such as
// screen_blur's), and an engine's own program drawing its own geometry
// around a function form. It is the GL counterpart of the Vulkan Engine's
// build_minmax, run_query, run_passes and run_surface, and like them each
// call is one run of the pass driver (penumbra/runtime/pass_driver.hpp) on
// the engine's GL device; no call names a technique.
//
// Lifecycle: GlEngine::create() opens an EGL display and a context; then any
// number of calls, from one thread at a time (each call makes the context
// current and restores whatever was current before it returns, and every
// call's GL work is finished when it returns); then destroy the engine.
// Every failure is a returned Error, never an exception.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

namespace gl {
struct Context;
}

struct GlEngineOptions {
  // "" opens the default display: Mesa's surfaceless platform
  // (EGL_MESA_platform_surfaceless) when the EGL library offers it, else
  // EGL_DEFAULT_DISPLAY with a 1x1 pbuffer. Otherwise an EGL device
  // (EGL_EXT_device_enumeration): its index ("0"), or a case-insensitive
  // substring of its GL_RENDERER ("llvmpipe"); the first match wins.
  std::string device;
};

struct GlInfo {
  std::string renderer;      // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;       // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  std::string glsl_version;  // GL_SHADING_LANGUAGE_VERSION, e.g. "4.50"
};

// One pass as a library holds it for one GLSL target: its two texts and
// their reflection. The engine reads all three through these references;
// they must outlive the call.
struct GlPass {
  std::string_view vert;             // the pass's vertex stage (fullscreen.vert) as emitted
  std::string_view frag;             // the pass's fragment stage as emitted
  const PassReflection& reflection;  // index.json's reflection.<pass>.<target>
};

// The passes that build the min-max mip (docs/shader-interface.md).
struct GlMinmaxPasses {
  GlPass init;    // minmax_init: the map -> level 1
  GlPass reduce;  // minmax_reduce: level l - 1 -> level l
};

struct GlQueryPasses {
  GlPass query;
  // Required when the query reads shadow_minmax, unused otherwise.
  std::optional<GlMinmaxPasses> minmax = std::nullopt;
};

// The query pass's output, each channel one image of the receivers' size,
// row 0 first.
struct GlQueryOutput {
  FloatImage visibility;   // .x
  FloatImage texel_reads;  // .y: the texels the pass counted as read per pixel
};

class GlEngine {
 public:
  // Opens the display `options` selects and a desktop GL 4.5 core context.
  // Errors: device when EGL, the display or a 4.5 core context is
  // unavailable; bad_input when a selector matches no EGL device (the message
  // lists them).
  static Result<std::unique_ptr<GlEngine>> create(const GlEngineOptions& options,
                                                  DiagnosticConsumer diagnostics);
  GlEngine(const GlEngine&) = delete;
  GlEngine& operator=(const GlEngine&) = delete;
  ~GlEngine();

  const GlInfo& info() const;

  // Compiles and links the query pass, binds it by its reflection, draws
  // one full-screen triangle into a target of the receivers' size in the
  // reflection's render-target format and reads it back. When the query
  // reads shadow_minmax, the mip is built first as build_minmax does.
  // `normalized_depth` is one channel of depth in [0, 1]; `receivers` holds
  // (u, v, z_r) in 3 or 4 channels. `params` maps ShadowParams member names
  // to vec4 values: every member a program uses must be present (the min-max
  // passes' source_size and screen_size are set per level); extra entries
  // are ignored. Errors, `where` naming the pass ("query pass",
  // "minmax_init pass", ...) or the input: compile (a stage's or the link's
  // log), bad_input (inputs; a program that disagrees with its reflection,
  // e.g. an active uniform the reflection lacks; a missing parameter; a
  // query reading shadow_minmax without `passes.minmax`), device. The map is
  // a `map_format` depth texture: an engine's D24 or D16 map holds values
  // those formats represent.
  Result<GlQueryOutput> run_query(const GlQueryPasses& passes, const FloatImage& normalized_depth,
                                  const FloatImage& receivers, const ParamBlock& params,
                                  DepthFormat map_format = DepthFormat::d32_float);

  // Runs a deferred pass (docs/deferred-mask.md) as run_query runs a query,
  // into a target of `camera_depth`'s size: `camera_depth` is one channel
  // of the camera's depth buffer as stored, row 0 first, uploaded as a
  // GL_DEPTH_COMPONENT32F texture. `params` holds the pass's matrices
  // besides ShadowParams' members. The map is a `map_format` depth texture
  // (an engine's D24 or D16 map holds values those formats represent). When
  // the pass reads shadow_minmax, `minmax` builds the mip first, as for a
  // query. Errors as run_query's, `where` "deferred pass".
  Result<GlQueryOutput> run_deferred(const GlPass& deferred, const FloatImage& normalized_depth,
                                     const FloatImage& camera_depth, const ParamBlock& params,
                                     DepthFormat map_format = DepthFormat::d32_float,
                                     const std::optional<GlMinmaxPasses>& minmax = std::nullopt);

  // Builds the min-max mip of `normalized_depth` with `passes` and reads it
  // back: levels 1..N (index 0 is level 1, ceil(W/2) x ceil(H/2); level N is
  // 1x1; N = max(1, ceil(log2(max(W, H))))), two channels (min, max) each.
  // Errors as run_query's.
  Result<std::vector<FloatImage>> build_minmax(const GlMinmaxPasses& passes,
                                               const FloatImage& normalized_depth,
                                               const ParamBlock& params);

  // Runs `passes`, a variant's pass list without its depth pass, on the
  // pass driver (penumbra/runtime/pass_driver.hpp): each pass with its text
  // from `programs`, full-screen over the screen `images` gives (the
  // receivers, or a camera's depth for a deferred pass; the scene colour for
  // a composite), each target the screen's size with screen_size set to it,
  // on `normalized_depth` as a `map_format` depth texture; the min-max
  // passes, where listed, build the mip of it first. Returns every screen
  // pass's target, all its channels (no GPU time). Errors as run_query's,
  // naming the pass.
  Result<runtime::PassOutputs> run_passes(std::span<const PassKind> passes,
                                          const std::map<PassKind, GlPass>& programs,
                                          const FloatImage& normalized_depth,
                                          const runtime::ScreenImages& images,
                                          const ParamBlock& params,
                                          DepthFormat map_format = DepthFormat::d32_float);

  // Draws `triangles` (a triangle list in whatever space the program's
  // vertex stage takes; the reflection's one vertex input, 3 floats) with
  // `surface`, an engine's own program whose fragment stage calls a
  // variant's function form (docs/function-form.md), into a width x height
  // target in the reflection's render-target format with a
  // GL_DEPTH_COMPONENT32F depth buffer of its own (both cleared to 1.0,
  // depth test LESS, no culling), `normalized_depth` bound as the function
  // form's textures, a `map_format` depth texture as run_deferred's, and the
  // min-max mip `minmax` builds of it when the function reads shadow_minmax.
  // Returns the target's channels, row 0 first. Errors as run_query's,
  // `where` "surface pass".
  Result<FloatImage> run_surface(const GlPass& surface,
                                 std::span<const std::array<float, 3>> triangles,
                                 const FloatImage& normalized_depth, int width, int height,
                                 const ParamBlock& params,
                                 DepthFormat map_format = DepthFormat::d32_float,
                                 const std::optional<GlMinmaxPasses>& minmax = std::nullopt);

 private:
  explicit GlEngine(std::unique_ptr<gl::Context> context);

  std::unique_ptr<gl::Context> context_;
};

}  // namespace penumbra
