#include "glslang_ast.hpp"

#include <glslang/Public/ResourceLimits.h>

#include <regex>
#include <sstream>
#include <vector>

#include "glsl/glslang_setup.hpp"

namespace penumbra::testing {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Folds a four-line access to a member of the built-in output block,
//   0:19  gl_Position: direct index for structure ( <type>)
//   0:19    'anon@1' ( out block{...})
//   0:19    Constant:
//   0:19      0 (const uint)
// into the one line a 3.00 text prints for the variable:
//   0:19  'gl_Position' ( <type>)
std::string fold_per_vertex_block(const std::vector<std::string>& lines) {
  static const std::regex member(R"(^(0:\S+\s+)(gl_\w+): direct index for structure (\(.*\))$)");
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (std::regex_match(lines[i], m, member) && i + 3 < lines.size() &&
        lines[i + 1].find("'anon@") != std::string::npos &&
        lines[i + 1].find(" out block{") != std::string::npos &&
        lines[i + 2].ends_with("Constant:") && lines[i + 3].ends_with(" (const uint)")) {
      out += m[1].str() + "'" + m[2].str() + "' " + m[3].str() + "\n";
      i += 3;
      continue;
    }
    if (!lines[i].starts_with("Shader version:")) out += lines[i] + "\n";
  }
  return out;
}

}  // namespace

std::string glslang_es_ast(const std::string& text, ShaderStage stage) {
  ensure_glslang_initialized();
  glslang::TShader shader(glslang_stage(stage));
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  if (!shader.parse(GetDefaultResources(), 100, false, EShMsgAST)) {
    return std::string("rejected: ") + shader.getInfoLog();
  }
  return fold_per_vertex_block(
      lines_of(std::string(shader.getInfoLog()) + shader.getInfoDebugLog()));
}

}  // namespace penumbra::testing
