#include "targets/dx9_constants.hpp"

#include <algorithm>
#include <regex>
#include <string>

namespace penumbra {

Result<std::string> dx9_constants_as_registers(const std::string& hlsl) {
  static const std::regex block(R"(cbuffer (\w+) : register\(b\d+\)\s*\{([^}]*)\};)");
  static const std::regex member(R"(^\s*(\w+) (\w+) : packoffset\(c(\d+)(\.[xyzw])?\);\s*$)");

  std::smatch match;
  if (!std::regex_search(hlsl, match, block)) return hlsl;  // no constants: nothing to do
  const std::string block_name = match[1];
  std::string replacement = "// " + block_name + " as Direct3D 9 constant registers\n";
  const std::string body = match[2];
  int next_register = 0;
  std::size_t start = 0;
  while (start < body.size()) {
    std::size_t end = body.find('\n', start);
    if (end == std::string::npos) end = body.size();
    const std::string line = body.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::smatch m;
    if (!std::regex_match(line, m, member) || m[1] != "float4" || m[4].matched) {
      return make_error(Error::Kind::compile, "hlsl_dx9 constants",
                        "uniform block " + block_name + " member '" + line +
                            "' is not a float4 at a whole register; Direct3D 9 constants are "
                            "float4 registers");
    }
    replacement += "uniform float4 " + m[2].str() + " : register(c" + m[3].str() + ");\n";
    next_register = std::max(next_register, std::stoi(m[3].str()) + 1);
  }
  std::string out = match.prefix().str() + replacement + match.suffix().str();
  // SPIRV-Cross declares its half-pixel constant without a register. FXC
  // would pick a free one, but other HLSL compilers (glslang) pack it at c0,
  // on top of the block: give it the first register after the block.
  static const std::regex half_pixel(R"(uniform float4 gl_HalfPixel;)");
  out = std::regex_replace(
      out, half_pixel,
      "uniform float4 gl_HalfPixel : register(c" + std::to_string(next_register) + ");");
  if (std::regex_search(out, block)) {
    return make_error(Error::Kind::compile, "hlsl_dx9 constants",
                      "more than one uniform block; Direct3D 9 has one constant register file");
  }
  return out;
}

}  // namespace penumbra
