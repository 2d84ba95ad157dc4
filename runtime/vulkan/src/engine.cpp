#include "penumbra/vulkan/engine.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "context.hpp"
#include "minmax_build.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image_checks.hpp"
#include "reflection_binding.hpp"
#include "shadow_map_images.hpp"
#include "shadow_map_transfer.hpp"
#include "vulkan_device.hpp"

namespace penumbra {
namespace {

// Images carry their device's handles, so another engine's map is unusable here.
Status check_owner(const detail::ShadowMapImages& images, const detail::Context& context) {
  if (images.device == context.device) return {};
  return make_error(Error::Kind::bad_input, "shadow map",
                    "was made by a different Engine; a shadow map works only with its own");
}

// Said here rather than as "nothing to bind": the map could have one.
Status check_mip(const PassProgram& program, const detail::ShadowMapImages& map,
                 std::string_view what) {
  if (map.minmax || !detail::reads_texture(program.reflection, TextureId::shadow_minmax)) return {};
  return make_error(Error::Kind::bad_input, std::string(what),
                    "the program reads shadow_minmax, the shadow map's min-max mip, but this " +
                        std::to_string(map.colour.desc().width) + "x" +
                        std::to_string(map.colour.desc().height) +
                        " map has none; build it first (Engine::build_minmax with the "
                        "variant's minmax_init and minmax_reduce passes)");
}

Status check_scene_colour(const FloatImage& scene_colour, const FloatImage& receivers) {
  if (scene_colour.width == receivers.width && scene_colour.height == receivers.height) return {};
  return make_error(Error::Kind::bad_input, "scene colour",
                    "is " + std::to_string(scene_colour.width) + "x" +
                        std::to_string(scene_colour.height) + " but the screen (receivers) is " +
                        std::to_string(receivers.width) + "x" + std::to_string(receivers.height));
}

// The map (and its mip, when built) as the passes' inputs on `device`.
runtime::PassInputs map_inputs(detail::VulkanDevice& device, detail::ShadowMapImages& map,
                               const ParamBlock& params) {
  runtime::PassInputs inputs;
  inputs.map = device.adopt(map);
  inputs.mip = device.adopt_mip(map);
  inputs.params = params;
  return inputs;
}

// `passes` on `map` over the screen `images` gives, every screen target
// read back (Engine::run_passes).
Result<runtime::PassOutputs> passes_on(detail::Context& context, detail::ShadowMapImages& map,
                                       std::span<const PassKind> passes,
                                       const PassProgramMap& programs,
                                       const runtime::ScreenImages& images,
                                       const ParamBlock& params) {
  const bool builds_mip = std::ranges::find(passes, PassKind::minmax_init) != passes.end();
  detail::VulkanDevice device(context);
  runtime::PassPrograms loaded;
  for (const auto& [pass, program] : programs) {
    if (!builds_mip) PENUMBRA_TRY(check_mip(*program, map, std::string(to_string(pass)) + " pass"));
    loaded[pass] = device.load(*program);
  }
  runtime::PassInputs inputs = map_inputs(device, map, params);
  PENUMBRA_TRY(runtime::upload_screen(device, images, passes, inputs));
  if (inputs.receivers && inputs.scene_colour) {
    PENUMBRA_TRY(check_scene_colour(*images.scene_colour, *images.receivers));
  }
  return runtime::run_and_read(device, passes, loaded, inputs);
}

// A query's or a deferred pass's (visibility, texel reads), split.
QueryOutput visibility_of(const runtime::PassOutputs& outputs) {
  const FloatImage& target = outputs.targets.front().second;
  return QueryOutput{channel(target, 0), channel(target, 1), outputs.gpu_ms};
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
    detail::VulkanDevice device(*context_);
    PENUMBRA_TRY_ASSIGN(const runtime::Texture drawn,
                        runtime::draw_map(device, device.load(depth), triangles, width, height,
                                          depth_format, params));
    return std::shared_ptr<ShadowMap>(new ShadowMap(device.take_map(drawn)));
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
    detail::VulkanDevice device(*context_);
    runtime::PassInputs inputs;
    inputs.map = device.adopt(*map.images_);
    inputs.params = params;
    const PassKind passes[] = {PassKind::minmax_init, PassKind::minmax_reduce};
    const runtime::PassPrograms programs = {{PassKind::minmax_init, device.load(init)},
                                            {PassKind::minmax_reduce, device.load(reduce)}};
    PENUMBRA_TRY_ASSIGN(runtime::PassResults results,
                        runtime::run_passes(device, passes, programs, inputs));
    return MinmaxBuild{static_cast<int>(results.levels.size()), results.gpu_ms};
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
    const PassKind passes[] = {PassKind::query};
    PENUMBRA_TRY_ASSIGN(runtime::PassOutputs outputs,
                        passes_on(*context_, *map.images_, passes, {{PassKind::query, &query}},
                                  {.receivers = &receivers}, params));
    return visibility_of(outputs);
  });
}

Result<QueryOutput> Engine::run_deferred(const PassProgram& deferred, const ShadowMap& map,
                                         const FloatImage& camera_depth, const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<QueryOutput> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    const PassKind passes[] = {PassKind::deferred};
    PENUMBRA_TRY_ASSIGN(
        runtime::PassOutputs outputs,
        passes_on(*context_, *map.images_, passes, {{PassKind::deferred, &deferred}},
                  {.camera_depth = &camera_depth}, params));
    return visibility_of(outputs);
  });
}

Result<FloatImage> Engine::run_surface(const PassProgram& surface,
                                       std::span<const std::array<float, 3>> triangles,
                                       const ShadowMap& map, int width, int height,
                                       const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<FloatImage> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    detail::VulkanDevice device(*context_);
    PENUMBRA_TRY_ASSIGN(
        runtime::Drawn drawn,
        runtime::draw_surface(device, device.load(surface), triangles, width, height,
                              device.adopt(*map.images_), device.adopt_mip(*map.images_), params));
    return device.read(drawn.target);
  });
}

Result<runtime::PassOutputs> Engine::run_passes(std::span<const PassKind> passes,
                                                const PassProgramMap& programs, ShadowMap& map,
                                                const runtime::ScreenImages& images,
                                                const ParamBlock& params) {
  return detail::run_validated(*context_->validation, [&]() -> Result<runtime::PassOutputs> {
    PENUMBRA_TRY(check_owner(*map.images_, *context_));
    return passes_on(*context_, *map.images_, passes, programs, images, params);
  });
}

Result<FloatImage> Engine::run_query(const PassProgram& query, const ShadowMap& map,
                                     const FloatImage& receivers, const ParamBlock& params) {
  auto output = run_query_output(query, map, receivers, params);
  if (!output) return output.error();
  return std::move(output->visibility);
}

}  // namespace penumbra
