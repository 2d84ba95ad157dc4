// `penumbra eval`: one variant's pass for one target over given inputs, on
// the device or with the CPU reference.
#pragma once

#include <array>
#include <optional>

#include "penumbra/library/library.hpp"
#include "penumbra/model/light.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

struct EvalInputs {
  FloatImage shadow_map;  // Pf, W x H: linear light-view z, or the stored values below
  FloatImage receivers;   // PF: (u, v, z_r) per pixel
  // Light size, frustum width, near plane, bias, filter radius; its defaults
  // are index.json's `defaults`, the light the shaders were verified with.
  LightParams light;
  // With a value, `shadow_map` is the map as an engine stored it: depth-buffer
  // values in [0, 1] in the variant's map encoding (linear: z / far), from a
  // projection with light.near_plane and this far plane. None: linear z, and
  // eval picks the far plane (a power of two beyond every depth).
  std::optional<double> stored_far;
  // Pf of the receivers' size, or empty: a pixel that is not 0 has no
  // receiver (an engine's sky). It is shaded as a NaN receiver, lit, and the
  // reference marks it Ambiguity::no_receiver.
  FloatImage no_receiver;
  // x, y, width, height in texels of `shadow_map`, row 0 first: the light's
  // tile, where `shadow_map` is an atlas of several lights' maps (an atlas
  // variant's, map_layout atlas). None: the whole map.
  std::optional<std::array<int, 4>> map_tile;
  // Layer, count: `shadow_map` stacks the count layers of a 2D array
  // texture, each of an equal share of its rows, layer 0 first, and the
  // light's is that layer (an array variant's, map_layout array). None: an
  // array variant's map is the array's one layer.
  std::optional<std::array<int, 2>> map_layer;
};

// The light options' range (lengths in light-view units; the bias and the
// filter radius share it): wide enough for any scene, narrow enough that the
// shaders' float32 products of them stay finite.
inline constexpr double kMinLightLength = 1e-6;  // frustum width, near plane, filter radius
inline constexpr double kMaxLightLength = 1e6;   // and light size (from 0), |bias|

// Checks the images (channels, sizes, no negative depth; a stored map's
// values in [0, 1], its far plane beyond the near one; a tile or a layer
// inside the map) and the light options (finite, in range); errors name the argument.
// NaN and infinite linear depths are allowed: every technique defines them
// (docs/robustness.md).
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
