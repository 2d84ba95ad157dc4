#include "targets/dx9_half_pixel.hpp"

namespace penumbra {

Result<std::string> dx9_half_pixel_after_flip(const std::string& hlsl) {
  if (hlsl.find("gl_HalfPixel") == std::string::npos) return hlsl;  // not a vertex shader
  // SPIRV-Cross's fixup, then its flip: both lines must be there, in order,
  // for the turned sign to mean what docs/engines/d3d9.md says.
  static const std::string fixup =
      "gl_Position.y = gl_Position.y + gl_HalfPixel.y * gl_Position.w;";
  static const std::string flip = "gl_Position.y = -gl_Position.y;";
  const std::size_t at = hlsl.find(fixup);
  if (at == std::string::npos || hlsl.find(flip, at) == std::string::npos ||
      hlsl.find(fixup, at + 1) != std::string::npos) {
    return make_error(Error::Kind::compile, "hlsl_dx9",
                      "SPIRV-Cross's half-pixel fixup is not the expected '" + fixup +
                          "' followed by '" + flip + "'; the D3D9 half-pixel shim cannot apply");
  }
  std::string out = hlsl;
  out.replace(at, fixup.size(), "gl_Position.y = gl_Position.y - gl_HalfPixel.y * gl_Position.w;");
  return out;
}

}  // namespace penumbra
