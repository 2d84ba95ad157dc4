#include "penumbra/gl/engine.hpp"

#include <utility>

#include "context_info.hpp"
#include "device_selection.hpp"
#include "minmax_mip.hpp"
#include "query_pass.hpp"
#include "screen_blur_chain.hpp"
#include "surface_pass.hpp"
#include "textures.hpp"

namespace penumbra {

namespace gl {

// What an engine owns: the context (and through it the display). Each call
// creates and deletes its own objects.
struct Context {
  EglContext egl;
  GlInfo info;
};

}  // namespace gl

Result<std::unique_ptr<GlEngine>> GlEngine::create(const GlEngineOptions& options,
                                                   DiagnosticConsumer diagnostics) {
  auto opened = gl::open_context(options.device);
  if (!opened) return opened.error();
  GlInfo info;
  {
    auto current = opened->context.make_current();
    if (!current) return current.error();
    info = gl::current_context_info();
  }
  if (diagnostics) {
    diagnostics(
        {Severity::note, "OpenGL", info.renderer + ", " + info.version + " on " + opened->display});
  }
  auto context =
      std::make_unique<gl::Context>(gl::Context{std::move(opened->context), std::move(info)});
  return std::unique_ptr<GlEngine>(new GlEngine(std::move(context)));
}

GlEngine::GlEngine(std::unique_ptr<gl::Context> context) : context_(std::move(context)) {}

GlEngine::~GlEngine() = default;

const GlInfo& GlEngine::info() const {
  return context_->info;
}

Result<GlQueryOutput> GlEngine::run_query(const GlQueryPasses& passes,
                                          const FloatImage& normalized_depth,
                                          const FloatImage& receivers, const ParamBlock& params,
                                          DepthFormat map_format) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  return gl::run_query_pass(passes, {normalized_depth, receivers, params, map_format});
}

Result<GlQueryOutput> GlEngine::run_deferred(const GlPass& deferred,
                                             const FloatImage& normalized_depth,
                                             const FloatImage& camera_depth,
                                             const ParamBlock& params, DepthFormat map_format,
                                             const std::optional<GlMinmaxPasses>& minmax) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  return gl::run_deferred_pass(deferred, normalized_depth, camera_depth, params, map_format,
                               minmax);
}

Result<FloatImage> GlEngine::run_surface(const GlPass& surface,
                                         std::span<const std::array<float, 3>> triangles,
                                         const FloatImage& normalized_depth, int width, int height,
                                         const ParamBlock& params, DepthFormat map_format,
                                         const std::optional<GlMinmaxPasses>& minmax) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  return gl::run_surface_pass(surface, triangles, normalized_depth, width, height, params,
                              map_format, minmax);
}

Result<std::vector<FloatImage>> GlEngine::build_minmax(const GlMinmaxPasses& passes,
                                                       const FloatImage& normalized_depth,
                                                       const ParamBlock& params) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  PENUMBRA_TRY(gl::check_shadow_map(normalized_depth));
  gl::PassInputs inputs;
  inputs.give(TextureId::shadow_depth, normalized_depth);
  auto mip = gl::build_minmax_mip(passes, inputs, {normalized_depth.width, normalized_depth.height},
                                  params);
  if (!mip) return mip.error();
  return gl::read_minmax_mip(*mip);
}

Result<GlScreenBlurOutput> GlEngine::run_screen_blur(const GlScreenBlurPasses& passes,
                                                     const FloatImage& normalized_depth,
                                                     const FloatImage& receivers,
                                                     const FloatImage& scene_colour,
                                                     const ParamBlock& params) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  return gl::run_screen_blur_chain(passes, {normalized_depth, receivers, scene_colour, params});
}

}  // namespace penumbra
