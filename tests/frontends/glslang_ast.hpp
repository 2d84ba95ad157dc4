// glslang's AST of a GLSL text, printed: what the text means to glslang,
// for tests that show a rewrite changes no meaning.
#pragma once

#include <string>

#include "penumbra/spirv/reflection.hpp"

namespace penumbra::testing {

// The AST of `text` parsed for OpenGL ES without SPIR-V rules, so that both
// ESSL 3.00 and 3.10 are accepted; "rejected: <log>" when glslang does not
// accept the text. Two differences of representation between the versions
// are folded away, nothing else:
//  - the "Shader version:" line is dropped;
//  - ESSL 3.10 declares the vertex outputs gl_Position and gl_PointSize as
//    members of an anonymous gl_PerVertex block, 3.00 as variables: an
//    access `gl_X: direct index for structure` of that block is printed as
//    the variable 'gl_X' of the same type (the same BuiltIn either way).
std::string glslang_es_ast(const std::string& text, ShaderStage stage);

}  // namespace penumbra::testing
