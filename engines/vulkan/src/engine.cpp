#include "penumbra/vulkan/engine.hpp"

#include <optional>
#include <utility>

#include "context.hpp"
#include "depth_pass.hpp"
#include "minmax_build.hpp"
#include "query_pass.hpp"
#include "screen_blur_chain.hpp"
#include "shadow_map_images.hpp"
#include "shadow_map_transfer.hpp"
#include "surface_pass.hpp"

namespace penumbra {
namespace {

// Images carry their device's handles, so another engine's map is unusable here.
Status check_owner(const detail::ShadowMapImages& images, const detail::Context& context) {
  if (images.device == context.device) return {};
  return make_error(Error::Kind::bad_input, "shadow map",
                    "was made by a different Engine; a shadow map works only with its own");
}

}  // namespace

Result<std::unique_ptr<Engine>> Engine::create(const EngineOptions& options,
                                               DiagnosticConsumer diagnostics) {
  auto context = detail::create_context(options, std::move(diagnostics));
  if (!context) return context.error();
  // Validation errors while opening the device fail creation too.
  if (std::optional<Error> error = (*context)->validation->end_call()) return *error;
  return std::unique_ptr<Engine>(new Engine(std::move(*context)));
}

Engine::Engine(std::unique_ptr<detail::Context> context) : context_(std::move(context)) {}

Engine::~Engine() = default;

const DeviceInfo& Engine::device_info() const {
  return context_->info;
}

Result<std::shared_ptr<ShadowMap>> Engine::render_depth(
    const PassProgram& depth, std::span<const std::array<float, 3>> triangles, int width,
    int height, const ParamBlock& params, DepthFormat depth_format) {
  return detail::run_validated(*context_->validation, [&]() -> Result<std::shared_ptr<ShadowMap>> {
    auto images =
        detail::render_depth(*context_, depth, triangles, width, height, params, depth_format);
    if (!images) return images.error();
    return std::shared_ptr<ShadowMap>(new ShadowMap(std::move(*images)));
  });
}

Result<std::shared_ptr<ShadowMap>> Engine::upload_shadow_map(const FloatImage& normalized_depth) {
  return detail::run_validated(*context_->validation, [&]() -> Result<std::shared_ptr<ShadowMap>> {
    auto images = detail::upload_shadow_map(*context_, normalized_depth);
    if (!images) return images.error();
    return std::shared_ptr<ShadowMap>(new ShadowMap(std::move(*images)));
  });
}

Result<FloatImage> Engine::read_shadow_map(const ShadowMap& map) {
  return detail::run_validated(*context_->validation, [&]() -> Result<FloatImage> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::read_shadow_map(*context_, *map.images_);
  });
}

Result<FloatImage> Engine::read_shadow_depth(const ShadowMap& map) {
  return detail::run_validated(*context_->validation, [&]() -> Result<FloatImage> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::read_shadow_depth(*context_, *map.images_);
  });
}

Result<MinmaxBuild> Engine::build_minmax(ShadowMap& map, const PassProgram& init,
                                         const PassProgram& reduce, const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<MinmaxBuild> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::build_minmax(*context_, *map.images_, init, reduce, params);
  });
}

Result<std::vector<FloatImage>> Engine::read_minmax(const ShadowMap& map) {
  return detail::run_validated(*context_->validation, [&]() -> Result<std::vector<FloatImage>> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::read_minmax(*context_, *map.images_);
  });
}

Result<QueryOutput> Engine::run_query_output(const PassProgram& query, const ShadowMap& map,
                                             const FloatImage& receivers,
                                             const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<QueryOutput> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::run_query(*context_, query, *map.images_, receivers, params);
  });
}

Result<QueryOutput> Engine::run_deferred(const PassProgram& deferred, const ShadowMap& map,
                                         const FloatImage& camera_depth, const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<QueryOutput> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::run_deferred(*context_, deferred, *map.images_, camera_depth, params);
  });
}

Result<FloatImage> Engine::run_surface(const PassProgram& surface,
                                       std::span<const std::array<float, 3>> triangles,
                                       const ShadowMap& map, int width, int height,
                                       const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<FloatImage> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::run_surface(*context_, surface, triangles, *map.images_, width, height, params);
  });
}

Result<ScreenBlurOutput> Engine::run_screen_blur(const ScreenBlurPrograms& programs,
                                                 const ShadowMap& map, const FloatImage& receivers,
                                                 const FloatImage& scene_colour,
                                                 const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<ScreenBlurOutput> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::run_screen_blur(*context_, programs, *map.images_, receivers, scene_colour,
                                   params);
  });
}

Result<FloatImage> Engine::run_query(const PassProgram& query, const ShadowMap& map,
                                     const FloatImage& receivers, const ParamBlock& params) {
  auto output = run_query_output(query, map, receivers, params);
  if (!output) return output.error();
  return std::move(output->visibility);
}

}  // namespace penumbra
