// The optional OpenGL path of verify: glsl330 and glsl450 text compiled by
// the GL driver (Mesa llvmpipe over EGL) instead of glslang, and bound by
// each pass's reflection in index.json, as a GL engine binds it. Present
// when the project is built with PENUMBRA_BUILD_GL; otherwise create() says
// why not.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "penumbra/compiler/library.hpp"
#include "penumbra/runtime/engine.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// One pass of a library for one target: its emitted texts and reflection.
struct GlPassTexts {
  std::string vert;
  std::string frag;
  PassReflection reflection;  // index.json's reflection.<pass>.<target>
};

// The passes that build the min-max mip.
struct GlMinmaxTexts {
  GlPassTexts init;    // minmax_init
  GlPassTexts reduce;  // minmax_reduce
};

struct GlQueryTexts {
  GlPassTexts query;
  // Required when the query reads shadow_minmax (a bad_input Error
  // otherwise), unused when it does not.
  std::optional<GlMinmaxTexts> minmax;
};

// screen_blur's chain.
struct GlScreenBlurTexts {
  GlPassTexts query;
  GlPassTexts blur_h;
  GlPassTexts blur_v;
  GlPassTexts composite;
};

// `entry`'s query pass for `target` and, for a technique that reads the
// min-max mip, the passes that build it. Errors: a file that cannot be read,
// a pass without a reflection for `target`.
Result<GlQueryTexts> read_gl_query(const Library& library, const LibraryVariant& entry,
                                   Target target);
// `entry`'s screen_blur chain for `target`; errors as read_gl_query's.
Result<GlScreenBlurTexts> read_gl_screen_blur(const Library& library, const LibraryVariant& entry,
                                              Target target);

class GlBackend {
 public:
  // Null when there is no GL path; `why_not` then says why. `device` selects
  // the GL device like penumbra::GlEngineOptions (verify passes "llvmpipe"
  // when Vulkan runs on lavapipe, so both paths use one rasterizer).
  static std::unique_ptr<GlBackend> create(const std::string& device, std::string& why_not);
  virtual ~GlBackend() = default;

  virtual std::string device() const = 0;
  // Builds the min-max mip when the query reads it, then runs the query
  // (GlEngine::run_query). The output's gpu_ms is always empty: GL's draws
  // are not timed.
  virtual Result<QueryOutput> run_query(const GlQueryTexts& texts,
                                        const FloatImage& normalized_depth,
                                        const FloatImage& receivers, const ParamBlock& params) = 0;
  // screen_blur's chain (GlEngine::run_screen_blur); gpu_ms is always empty.
  virtual Result<ScreenBlurOutput> run_screen_blur(const GlScreenBlurTexts& texts,
                                                   const FloatImage& normalized_depth,
                                                   const FloatImage& receivers,
                                                   const FloatImage& scene_colour,
                                                   const ParamBlock& params) = 0;
};

}  // namespace penumbra
