// An engine's own geometry drawn with its own program: the GL counterpart
// of the Vulkan engine's run_surface (docs/function-form.md).
#pragma once

#include <array>
#include <optional>
#include <span>

#include "penumbra/gl/engine.hpp"

namespace penumbra::gl {

// See GlEngine::run_surface.
Result<FloatImage> run_surface_pass(const GlPass& surface,
                                    std::span<const std::array<float, 3>> triangles,
                                    const FloatImage& normalized_depth, int width, int height,
                                    const ParamBlock& params, DepthFormat map_format,
                                    const std::optional<GlMinmaxPasses>& minmax);

}  // namespace penumbra::gl
