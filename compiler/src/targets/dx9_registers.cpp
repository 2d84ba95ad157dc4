#include "targets/dx9_registers.hpp"

#include <algorithm>
#include <regex>
#include <string>

#include "penumbra/model/shader_contract.hpp"

namespace penumbra {
namespace {

Error fail(std::string message) {
  return make_error(Error::Kind::compile, "hlsl_dx9 registers", std::move(message));
}

// The cbuffer as constant registers; `next_register` is set past the last.
Result<std::string> constants_as_registers(const std::string& hlsl, int& next_register) {
  static const std::regex block(R"(cbuffer (\w+) : register\(b\d+\)\s*\{([^}]*)\};)");
  static const std::regex member(R"(^\s*(\w+) (\w+) : packoffset\(c(\d+)(\.[xyzw])?\);\s*$)");

  std::smatch match;
  if (!std::regex_search(hlsl, match, block)) return hlsl;  // no constants: nothing to do
  const std::string block_name = match[1];
  std::string replacement = "// " + block_name + " as Direct3D 9 constant registers\n";
  const std::string body = match[2];
  std::size_t start = 0;
  while (start < body.size()) {
    std::size_t end = body.find('\n', start);
    if (end == std::string::npos) end = body.size();
    const std::string line = body.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::smatch m;
    if (!std::regex_match(line, m, member) || m[1] != "float4" || m[4].matched) {
      return fail("uniform block " + block_name + " member '" + line +
                  "' is not a float4 at a whole register; Direct3D 9 constants are float4 "
                  "registers");
    }
    replacement += "uniform float4 " + m[2].str() + " : register(c" + m[3].str() + ");\n";
    next_register = std::max(next_register, std::stoi(m[3].str()) + 1);
  }
  std::string out = match.prefix().str() + replacement + match.suffix().str();
  if (std::regex_search(out, block)) {
    return fail("more than one uniform block; Direct3D 9 has one constant register file");
  }
  return out;
}

// Every sampler at s<slot>, its slot in shader_contract.hpp.
Result<std::string> samplers_at_slots(const std::string& hlsl, std::string_view prefix) {
  static const std::regex sampler(R"(uniform sampler2D (\w+);)");
  std::string out;
  auto begin = std::sregex_iterator(hlsl.begin(), hlsl.end(), sampler);
  std::size_t copied = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    const TextureDescription* texture =
        name.starts_with(prefix) ? find_texture(std::string_view(name).substr(prefix.size()))
                                 : nullptr;
    if (!texture) {
      return fail("sampler '" + name + "' is not a texture of the shader contract");
    }
    out += hlsl.substr(copied, static_cast<std::size_t>(it->position()) - copied);
    out += "uniform sampler2D " + name + " : register(s" + std::to_string(texture->slot) + ");";
    copied = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + hlsl.substr(copied);
}

}  // namespace

Result<std::string> dx9_explicit_registers(const std::string& hlsl, std::string_view prefix) {
  int next_register = 0;
  auto constants = constants_as_registers(hlsl, next_register);
  if (!constants) return constants.error();
  // SPIRV-Cross declares its half-pixel constant without a register. FXC
  // would pick a free one, and other HLSL compilers (glslang) pack it at c0,
  // on top of the block: pin it where the reflection says it is. Only
  // vertex shaders declare it; pixel shaders have a register file of their
  // own, which the deferred pass fills past it.
  static const std::regex half_pixel_decl(R"(uniform float4 gl_HalfPixel;)");
  const int half_pixel = static_cast<int>(half_pixel_register());
  if (next_register > half_pixel && std::regex_search(*constants, half_pixel_decl)) {
    return fail("the constants reach c" + std::to_string(next_register - 1) + ", past c" +
                std::to_string(half_pixel - 1) + "; gl_HalfPixel is pinned at c" +
                std::to_string(half_pixel));
  }
  const std::string pinned = std::regex_replace(
      *constants, half_pixel_decl,
      "uniform float4 gl_HalfPixel : register(c" + std::to_string(half_pixel) + ");");
  return samplers_at_slots(pinned, prefix);
}

}  // namespace penumbra
