#include "penumbra/runtime/engine.hpp"

#include <optional>
#include <utility>

#include "context.hpp"
#include "depth_pass.hpp"
#include "query_pass.hpp"
#include "shadow_map_images.hpp"
#include "shadow_map_transfer.hpp"

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
    int height, const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<std::shared_ptr<ShadowMap>> {
    auto images = detail::render_depth(*context_, depth, triangles, width, height, params);
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

Result<FloatImage> Engine::run_query(const PassProgram& query, const ShadowMap& map,
                                     const FloatImage& receivers, const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<FloatImage> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return detail::run_query(*context_, query, *map.images_, receivers, params);
  });
}

}  // namespace penumbra
