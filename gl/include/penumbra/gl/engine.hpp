// GlEngine: runs a query pass's GLSL text (glsl330 or glsl450 as emitted) on
// an OpenGL 4.5 core context over headless EGL, normally Mesa's llvmpipe
// (docs/gl.md), building the shadow map's min-max mip first with the
// variant's own passes when the query reads it. It is the GL counterpart of
// the Vulkan Engine's build_minmax and run_query.
//
// Lifecycle: GlEngine::create() opens an EGL display and a context; then any
// number of run_query / build_minmax calls, from one thread at a time (each
// call makes the context current and restores whatever was current before
// it returns, and every call's GL work is finished when it returns); then
// destroy the engine. Every failure is a returned Error, never an exception.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// One pass's text as emitted: fullscreen.vert compiled for the pass, and the
// pass's fragment stage.
struct GlPass {
  std::string_view vert;
  std::string_view frag;
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

// The query pass's RG32F output, each channel one image of the receivers'
// size, row 0 first.
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

  // Compiles and links the query pass, binds ShadowParams and the samplers
  // by name, draws one full-screen triangle into an RG32F target of the
  // receivers' size and reads it back. When the query reads shadow_minmax,
  // the mip is built first as build_minmax does. `normalized_depth` is one
  // channel of depth in [0, 1]; `receivers` holds (u, v, z_r) in 3 or 4
  // channels. `params` maps ShadowParams member names to vec4 values: every
  // member a program uses must be present (the min-max passes' source_size
  // and screen_size are set per level); extra entries are ignored.
  // Errors, `where` naming the pass ("query pass", "minmax_init pass",
  // "minmax_reduce pass") or the input: compile (a stage's or the link's
  // log), bad_input (inputs, a name outside the shader interface, a missing
  // parameter, or a query reading shadow_minmax without `passes.minmax`),
  // device.
  Result<GlQueryOutput> run_query(const GlQueryPasses& passes, const FloatImage& normalized_depth,
                                  const FloatImage& receivers, const ParamBlock& params);

  // Builds the min-max mip of `normalized_depth` with `passes` and reads it
  // back: levels 1..N (index 0 is level 1, ceil(W/2) x ceil(H/2); level N is
  // 1x1; N = max(1, ceil(log2(max(W, H))))), two channels (min, max) each.
  // Errors as run_query's.
  Result<std::vector<FloatImage>> build_minmax(const GlMinmaxPasses& passes,
                                               const FloatImage& normalized_depth,
                                               const ParamBlock& params);

 private:
  explicit GlEngine(std::unique_ptr<gl::Context> context);

  std::unique_ptr<gl::Context> context_;
};

}  // namespace penumbra
