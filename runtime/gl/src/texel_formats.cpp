#include "texel_formats.hpp"

#include <cstddef>
#include <string>

namespace penumbra::gl {
namespace {

// Every texture of shader_contract.hpp holds 32-bit floats (or 32-bit float
// depth). Indexed by TextureFormat.
constexpr TexelFormat kFormats[] = {
    {TextureFormat::r32_float, GL_R32F, GL_RED, 1},
    {TextureFormat::rg32_float, GL_RG32F, GL_RG, 2},
    {TextureFormat::rgba32_float, GL_RGBA32F, GL_RGBA, 4},
    {TextureFormat::d32_float, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, 1},
};

// Indexed by DepthFormat. Uploads pass floats; GL rounds them to the unorm
// codes, which the maps' values already are.
constexpr TexelFormat kDepthFormats[] = {
    kFormats[static_cast<std::size_t>(TextureFormat::d32_float)],
    {TextureFormat::d32_float, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, 1, "GL_DEPTH_COMPONENT24"},
    {TextureFormat::d32_float, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, 1, "GL_DEPTH_COMPONENT16"},
};

}  // namespace

const TexelFormat& depth_texel_format(DepthFormat format) {
  return kDepthFormats[static_cast<std::size_t>(format)];
}

Result<const TexelFormat*> texel_format(std::string_view name, const std::string& where,
                                        const std::string& what) {
  if (auto format = parse_api_format(Target::glsl450, name)) {
    return &kFormats[static_cast<std::size_t>(*format)];
  }
  return make_error(Error::Kind::bad_input, where,
                    what + " has format '" + std::string(name) +
                        "', which the GL engine does not create; it creates " +
                        allowed_api_formats(Target::glsl450));
}

}  // namespace penumbra::gl
