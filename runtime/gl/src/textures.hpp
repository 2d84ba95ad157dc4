// The passes' images as GL textures, in the formats the reflection names
// (texel_formats.hpp): the caller's images uploaded, the passes' targets,
// the min-max mip's chain, and readbacks. Row 0 of an image is GL's first
// row (t = 0, window y = 0), docs/shader-interface.md's row j = 0: nothing flips.
#pragma once

#include <string>

#include "gl_names.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"
#include "texel_formats.hpp"

namespace penumbra::gl {

// Errors (bad_input): those of check_normalized_depth
// (penumbra/support/image_checks.hpp), or the map is empty or larger than
// GL_MAX_TEXTURE_SIZE.
Status check_shadow_map(const FloatImage& normalized_depth);

// check_shadow_map, and for the receivers likewise with check_receivers.
Status check_query_inputs(const FloatImage& normalized_depth, const FloatImage& receivers);

// Errors (bad_input, "scene colour"): not four channels of the receivers' size.
Status check_scene_colour(const FloatImage& scene_colour, const FloatImage& receivers);

// One immutable level in `format` holding `image`, which has at most the
// format's channels; channels the image lacks are zero (receivers' (u, v,
// z_r) in GL_RGBA32F). An image with layers is a GL_TEXTURE_2D_ARRAY. Errors (device): a GL error.
// `what` names it in errors.
Result<Texture> upload(const FloatImage& image, const TexelFormat& format, const std::string& what);

// One level in `format`, a pass's colour target.
Result<Texture> create_target(const TexelFormat& format, int width, int height,
                              const std::string& what);

// `levels` levels in `format`, level 0 `side` x `side`, every texel 1 in
// every channel. Errors (device): a GL error.
Result<Texture> create_chain(const TexelFormat& format, int side, int levels,
                             const std::string& what);

// Texels [0, width) x [0, height) of `level`, every channel of `format`.
// Errors (device): a GL error.
Result<FloatImage> read_texture(const Texture& texture, const TexelFormat& format, int level,
                                int width, int height, const std::string& what);

}  // namespace penumbra::gl
