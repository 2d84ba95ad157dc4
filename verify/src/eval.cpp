#include "penumbra/verify/eval.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/shadow_params.hpp"
#include "penumbra/vulkan/library_programs.hpp"

namespace penumbra {
namespace {

bool all_finite(const FloatImage& image) {
  return std::all_of(image.data.begin(), image.data.end(),
                     [](float v) { return std::isfinite(v); });
}

// The largest depth either input holds: the far end of the normalized range.
double max_depth(const EvalInputs& inputs) {
  double max_z = *std::max_element(inputs.shadow_map.data.begin(), inputs.shadow_map.data.end());
  for (std::size_t p = 0; p < inputs.receivers.pixel_count(); ++p) {
    max_z = std::max(max_z, double(inputs.receivers.data[p * 3 + 2]));
  }
  return max_z;
}

// screen_blur's chain: the receivers image is the screen; the blurred factor
// is the visibility, the factor pass's reads the texel reads. The composite
// is drawn over reference::scene_colour but not returned.
Result<QueryOutput> eval_screen_blur(const Library& library, const LibraryVariant& variant,
                                     Target target, const EvalInputs& inputs, const ShadowMap& map,
                                     const ParamBlock& params, Engine& engine) {
  auto programs = load_screen_blur(library, variant, target);
  if (!programs) return programs.error();
  const FloatImage colour =
      reference::scene_colour(inputs.receivers.width, inputs.receivers.height);
  auto chain = engine.run_screen_blur(programs->programs(), map, inputs.receivers, colour, params);
  if (!chain) return chain.error();
  return QueryOutput{std::move(chain->blurred), std::move(chain->texel_reads), chain->gpu_ms};
}

}  // namespace

Status check_eval_inputs(const EvalInputs& inputs) {
  if (inputs.shadow_map.channels != 1 || inputs.shadow_map.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "--shadow-map",
                      "expected a one-channel (Pf) image of linear light-view z");
  }
  if (inputs.receivers.channels != 3 || inputs.receivers.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "--receivers",
                      "expected a three-channel (PF) image of (u, v, z_r)");
  }
  if (!all_finite(inputs.shadow_map)) {
    return make_error(Error::Kind::bad_input, "--shadow-map", "holds a NaN or infinite depth");
  }
  if (!all_finite(inputs.receivers)) {
    return make_error(Error::Kind::bad_input, "--receivers", "holds a NaN or infinite value");
  }
  if (*std::min_element(inputs.shadow_map.data.begin(), inputs.shadow_map.data.end()) < 0.0f) {
    return make_error(Error::Kind::bad_input, "--shadow-map",
                      "holds a negative depth; linear light-view z is >= 0");
  }
  return {};
}

Result<QueryOutput> eval_on_device(const Library& library, const LibraryVariant& variant,
                                   Target target, const EvalInputs& inputs, Engine& engine) {
  PENUMBRA_TRY(check_eval_inputs(inputs));
  const float depth_scale = depth_scale_for(max_depth(inputs));
  FloatImage normalized = inputs.shadow_map;
  for (float& d : normalized.data) d *= depth_scale;  // exact: a power of two
  auto map = engine.upload_shadow_map(normalized);
  if (!map) return map.error();
  const ParamBlock params = shadow_params(inputs.light,
                                          {inputs.shadow_map.width, inputs.shadow_map.height,
                                           inputs.receivers.width, inputs.receivers.height},
                                          depth_scale);
  if (variant.variant.technique == Technique::screen_blur) {
    return eval_screen_blur(library, variant, target, inputs, **map, params, engine);
  }
  auto program = load_executable(library, variant, PassKind::query, target);
  if (!program) return program.error();
  if (uses_minmax_mip(variant.variant.technique)) {
    auto init = load_executable(library, variant, PassKind::minmax_init, target);
    if (!init) return init.error();
    auto reduce = load_executable(library, variant, PassKind::minmax_reduce, target);
    if (!reduce) return reduce.error();
    auto built = engine.build_minmax(**map, init->program, reduce->program, params);
    if (!built) return built.error();
  }
  return engine.run_query_output(program->program, **map, inputs.receivers, params);
}

Result<FloatImage> eval_reference(const LibraryVariant& variant, const EvalInputs& inputs) {
  PENUMBRA_TRY(check_eval_inputs(inputs));
  auto image =
      reference::evaluate_image(variant.variant, inputs.shadow_map, inputs.light, inputs.receivers);
  if (!image) return image.error();
  if (variant.variant.technique == Technique::screen_blur) {
    return reference::screen_blur(variant.variant, image->visibility, inputs.receivers);
  }
  return std::move(image->visibility);
}

}  // namespace penumbra
