// The GL texture formats a reflection names ("GL_RG32F", ...) as the GL
// calls that create, fill and read them take them.
#pragma once

#include <string_view>

#include "gl_api.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

struct TexelFormat {
  TextureFormat format;
  GLenum internal_format;
  GLenum pixel_format;  // of uploads and readbacks, as floats: GL_RG, GL_DEPTH_COMPONENT
  int channels;
  // The internal format's name where it is not the reflection's: a D24 or
  // D16 map standing for GL_DEPTH_COMPONENT32F.
  std::string_view internal_name = {};

  // As the reflection writes it, "GL_RG32F" (api_format()), or internal_name.
  std::string_view name() const {
    return internal_name.empty() ? api_format(Target::glsl450, format) : internal_name;
  }
};

// The format named `name`. Errors (bad_input, `where`): a name outside the
// 32-bit float formats the engine creates (GL_R32F, GL_RG32F, GL_RGBA32F,
// GL_DEPTH_COMPONENT32F); `what` says whose format it is.
Result<const TexelFormat*> texel_format(std::string_view name, const std::string& where,
                                        const std::string& what);

// The depth texture a `format` map is: GL_DEPTH_COMPONENT32F, 24 or 16, each
// read where the reflection says GL_DEPTH_COMPONENT32F.
const TexelFormat& depth_texel_format(DepthFormat format);

}  // namespace penumbra::gl
