// The depth pass: shadow casters into a new shadow map.
#pragma once

#include <array>
#include <memory>
#include <span>

#include "context.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::render_depth. Leaves both images in their resting layouts.
Result<std::unique_ptr<ShadowMapImages>> render_depth(
    Context& context, const PassProgram& program, std::span<const std::array<float, 3>> triangles,
    int width, int height, const ParamBlock& params, DepthFormat depth_format);

}  // namespace penumbra::detail
