// The query pass's images as GL textures: the shadow map as normalized depth
// in a GL_DEPTH_COMPONENT32F texture, the receivers as GL_RGBA32F and the
// output as GL_R32F (docs/shader-interface.md). Row 0 of an image is GL's
// first row (t = 0, window y = 0), the contract's row j = 0: nothing flips.
#pragma once

#include "gl_names.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Errors (bad_input): those of check_normalized_depth and check_receivers
// (penumbra/support/image_checks.hpp), or either image is empty or larger
// than GL_MAX_TEXTURE_SIZE.
Status check_query_inputs(const FloatImage& normalized_depth, const FloatImage& receivers);

// One immutable level; the sampler objects decide filtering.
Result<Texture> upload_depth(const FloatImage& normalized_depth);
Result<Texture> upload_receivers(const FloatImage& receivers);  // 3 channels padded to 4
Result<Texture> create_visibility_target(int width, int height);

}  // namespace penumbra::gl
