// The surface pass: an engine's own program drawing geometry with a depth
// buffer, its fragment stage calling a variant's function form
// (docs/function-form.md), which reads the shadow map.
#pragma once

#include <array>
#include <span>

#include "context.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::run_surface.
Result<FloatImage> run_surface(Context& context, const PassProgram& program,
                               std::span<const std::array<float, 3>> triangles,
                               const ShadowMapImages& map, int width, int height,
                               const ParamBlock& params);

}  // namespace penumbra::detail
