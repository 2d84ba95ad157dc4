#include "texel_formats.hpp"

#include <string>

namespace penumbra::gl {
namespace {

// Every texture of shader_contract.hpp holds 32-bit floats (or 32-bit float depth).
constexpr TexelFormat kFormats[] = {
    {"GL_R32F", GL_R32F, GL_RED, 1},
    {"GL_RG32F", GL_RG32F, GL_RG, 2},
    {"GL_RGBA32F", GL_RGBA32F, GL_RGBA, 4},
    {"GL_DEPTH_COMPONENT32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, 1},
};

}  // namespace

Result<const TexelFormat*> texel_format(std::string_view name, const std::string& where,
                                        const std::string& what) {
  std::string known;
  for (const TexelFormat& format : kFormats) {
    if (format.name == name) return &format;
    known += (known.empty() ? "" : ", ") + std::string(format.name);
  }
  return make_error(Error::Kind::bad_input, where,
                    what + " has format '" + std::string(name) +
                        "', which the GL engine does not create; it creates " + known);
}

}  // namespace penumbra::gl
