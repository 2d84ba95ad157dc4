// GlEngine: runs a query pass's GLSL text (glsl330 or glsl450 as emitted) on
// an OpenGL 4.5 core context over headless EGL, normally Mesa's llvmpipe
// (docs/gl.md). It is the GL counterpart of the Vulkan Engine's run_query.
//
// Lifecycle: GlEngine::create() opens an EGL display and a context; then any
// number of run_query calls, from one thread at a time (each call makes the
// context current and restores whatever was current before it returns, and
// every call's GL work is finished when it returns); then destroy the engine.
// Every failure is a returned Error, never an exception.
#pragma once

#include <memory>
#include <string>
#include <string_view>

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

  // Compiles and links `vertex_text` (fullscreen.vert) and `fragment_text`
  // (query.frag), binds ShadowParams and the samplers by name, draws one
  // full-screen triangle into an R32F target of the receivers' size and reads
  // it back (one channel, row 0 first). `normalized_depth` is one channel of
  // depth in [0, 1]; `receivers` holds (u, v, z_r) in 3 or 4 channels.
  // `params` maps ShadowParams member names to vec4 values: every member the
  // program uses must be present; extra entries are ignored.
  // Errors: compile (a stage's or the link's log), bad_input (inputs, or a
  // name outside the shader interface, or a missing parameter), device.
  Result<FloatImage> run_query(std::string_view vertex_text, std::string_view fragment_text,
                               const FloatImage& normalized_depth, const FloatImage& receivers,
                               const ParamBlock& params);

 private:
  explicit GlEngine(std::unique_ptr<gl::Context> context);

  std::unique_ptr<gl::Context> context_;
};

}  // namespace penumbra
