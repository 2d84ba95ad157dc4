// A linked program's uniforms, blocks and textures placed by the pass's
// reflection (index.json's reflection.<pass>.<target>), the way a GL engine
// that drops the library in binds them: by the reflection's exact names,
// offsets and bindings, never by a table of its own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl_api.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// A loose uniform the program uses (glsl330's "params.light").
struct UniformSlot {
  const ConstantBinding* constant = nullptr;  // in the reflection
  GLint location = -1;
};

// A uniform block the program uses (glsl450's ShadowParams): a buffer of
// the reflection's size, filled at its members' offsets, bound at `binding`.
struct BlockSlot {
  const BlockBinding* block = nullptr;  // in the reflection
  GLuint binding = 0;                   // the reflection's, or assigned
  // The members the program uses; the others are left zero.
  std::vector<const ConstantBinding*> members;
};

// A texture the program samples, shader_contract.hpp's image `texture` on `unit`.
struct TextureSlot {
  const TextureBinding* binding = nullptr;  // in the reflection
  TextureId texture = TextureId::shadow_depth;
  GLuint unit = 0;
};

struct PassBindings {
  std::vector<UniformSlot> uniforms;
  std::vector<BlockSlot> blocks;
  std::vector<TextureSlot> textures;
};

// Looks up every name of the reflection's stages in `program`
// (glGetUniformLocation, glGetUniformBlockIndex, glGetUniformIndices); a
// name the program does not know is skipped (GL drops inactive uniforms).
// Textures with a binding (glsl450) keep it; the others get the lowest free
// units, set with glProgramUniform1i. Blocks with a binding keep it; the
// others get one with glUniformBlockBinding. The reflection refers to
// `reflection`, which must outlive the result. Errors (bad_input, `where`):
// an active uniform or block the reflection lacks (naming it); a type,
// binding, block size or member offset the program reports otherwise than
// the reflection; two textures on one unit or a unit GL does not have; a
// texture name outside the shader contract.
Result<PassBindings> bind_by_reflection(GLuint program, const PassReflection& reflection,
                                        const std::string& where);

}  // namespace penumbra::gl
