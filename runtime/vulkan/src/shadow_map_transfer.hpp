// Shadow maps to and from the host.
#pragma once

#include <memory>

#include "context.hpp"
#include "penumbra/support/image.hpp"
#include "shadow_map_images.hpp"

namespace penumbra::detail {

// See Engine::upload_shadow_map. Leaves both images in their resting layouts.
Result<std::unique_ptr<ShadowMapImages>> upload_shadow_map(Context& context,
                                                           const FloatImage& normalized_depth);

// See Engine::read_shadow_map and read_shadow_depth.
Result<FloatImage> read_shadow_map(Context& context, const ShadowMapImages& map);
Result<FloatImage> read_shadow_depth(Context& context, const ShadowMapImages& map);

}  // namespace penumbra::detail
