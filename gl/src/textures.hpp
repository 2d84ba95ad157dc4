// The passes' images as GL textures: the shadow map as normalized depth in a
// GL_DEPTH_COMPONENT32F texture, the receivers as GL_RGBA32F, the query's
// output and the min-max levels as GL_RG32F (docs/shader-interface.md). Row 0
// of an image is GL's first row (t = 0, window y = 0), the contract's row
// j = 0: nothing flips.
#pragma once

#include <string>

#include "gl_names.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Errors (bad_input): those of check_normalized_depth
// (penumbra/support/image_checks.hpp), or the map is empty or larger than
// GL_MAX_TEXTURE_SIZE.
Status check_shadow_map(const FloatImage& normalized_depth);

// check_shadow_map, and for the receivers likewise with check_receivers.
Status check_query_inputs(const FloatImage& normalized_depth, const FloatImage& receivers);

// One immutable level; the sampler objects decide filtering.
Result<Texture> upload_depth(const FloatImage& normalized_depth);
Result<Texture> upload_receivers(const FloatImage& receivers);  // 3 channels padded to 4
// One level of GL_RG32F: the query pass's (visibility, texel reads) and each
// min-max pass's (min, max). `what` names it in errors.
Result<Texture> create_rg_target(int width, int height, const std::string& what);

// A GL_RG32F texture of `levels` levels, level 0 `side` x `side`, every texel
// (1, 1). Errors (device): a GL error.
Result<Texture> create_rg_chain(int side, int levels, const std::string& what);

// Texels [0, width) x [0, height) of `level` of a GL_RG32F texture, two
// channels. Errors (device): a GL error.
Result<FloatImage> read_rg(const Texture& texture, int level, int width, int height,
                           const std::string& what);

}  // namespace penumbra::gl
