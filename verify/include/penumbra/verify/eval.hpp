// `penumbra eval`: one variant's pass for one target over given inputs, on
// the device or with the CPU reference.
#pragma once

#include "penumbra/library/library.hpp"
#include "penumbra/model/light.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

struct EvalInputs {
  FloatImage shadow_map;  // Pf: linear light-view z, W x H
  FloatImage receivers;   // PF: (u, v, z_r) per pixel
  // Light size, frustum width, near plane, bias, filter radius; its defaults
  // are index.json's `defaults`, the light the shaders were verified with.
  LightParams light;
};

// The light options' range (lengths in light-view units; the bias and the
// filter radius share it): wide enough for any scene, narrow enough that the
// shaders' float32 products of them stay finite.
inline constexpr double kMinLightLength = 1e-6;  // frustum width, near plane, filter radius
inline constexpr double kMaxLightLength = 1e6;   // and light size (from 0), |bias|

// Checks the images (channels, sizes, no negative depth) and the light
// options (finite, in range); errors name the argument. NaN and infinite
// depths are allowed: every technique defines them (docs/robustness.md).
Status check_eval_inputs(const EvalInputs& inputs);

// The visibility image (Pf, the receivers' size) from the device, with the
// texel reads the pass counted and its GPU time (Engine::run_query_output).
// A technique that reads the min-max mip gets it built first by the target's
// own minmax_init and minmax_reduce passes. For screen_blur (the receivers
// image is the screen) the visibility is the blurred factor from the chain
// (its pass list run by Engine::run_passes) and the texel reads the factor
// pass's...
Result<QueryOutput> eval_on_device(const Library& library, const LibraryVariant& variant,
                                   Target target, const EvalInputs& inputs, Engine& engine);

// ...or from the CPU reference of `target`'s shader, under its limits
// (reference::shader_limits(), as verify holds that target): the visibility
// (for screen_blur, reference::screen_blur of the reference factor) and the
// reference's ambiguity mask, each pixel its reference::Ambiguity bits (for
// screen_blur, the factor's).
Result<reference::ReferenceImage> eval_reference(const LibraryVariant& variant, Target target,
                                                 const EvalInputs& inputs);

}  // namespace penumbra
