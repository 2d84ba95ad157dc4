// What a linked query program uses, found by name through GL's program
// introspection (the GL counterpart of the runtime's SPIR-V reflection), and
// checked against docs/shader-interface.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gl_api.hpp"
#include "pass_role.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// An active sampler: one of kImageSlots' names, with its type.
struct SamplerUniform {
  std::string name;
  GLint location = -1;
};

// An active ShadowParams member (always a vec4). In a uniform block it has
// an offset; as a plain uniform (GLSL 3.30's `uniform ShadowParams params;`)
// a location.
struct ParamMember {
  std::string member;  // "shadow_map_size", without "params." or "ShadowParams."
  GLint location = -1;
  GLint offset = -1;
};

// The std140 uniform block ShadowParams (GLSL 4.50).
struct ParamBlockInfo {
  GLint binding = 0;
  GLint size = 0;
};

struct ProgramInterface {
  std::vector<SamplerUniform> samplers;
  std::vector<ParamMember> members;
  std::optional<ParamBlockInfo> block;  // empty: members are plain uniforms
};

// Lists the program's active uniforms and blocks. Errors (bad_input, `where`
// = role.where) name anything outside the interface and what is allowed: a
// block other than ShadowParams, a uniform other than its members and the
// role's images, a sampler of the wrong type, a member that is not a vec4,
// or no active input image (role.images[0]).
Result<ProgramInterface> reflect_program(GLuint program, const PassRole& role);

}  // namespace penumbra::gl
