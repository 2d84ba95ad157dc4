// The per-target proofs of index.json's reflection: each reads one pass of
// one variant as a parser that is not the generator sees the emitted files
// (SPIRV-Cross, Mesa's OpenGL and OpenGL ES, glslang's ESSL and HLSL front
// ends) and compares with LibraryVariant::reflection in both directions:
// every reflection entry is in the text, with the same name, register,
// binding, offset and type, and everything the text declares that the API
// reports is in the reflection.
//
// Both sides are written as Facts, one line per entry ("frag texture
// shadow_cmp" -> "binding 2, sampler2DShadow"), and compared by
// compare_facts(): every difference is one line of the error.
#pragma once

#include <map>
#include <string>

#include "penumbra/compiler/library.hpp"

namespace penumbra::testing {

// Entry ("frag uniform params.light", prefixed by stage_key()) -> what the
// side says of it.
using Facts = std::map<std::string, std::string>;

// Ok when `reflected` and `observed` are equal; else an error at
// "<variant>, <pass> pass, <target>" listing each entry that differs, is
// missing from the text or is missing from the reflection. `parser` names
// the observing side in the message ("SPIRV-Cross").
Status compare_facts(const LibraryVariant& variant, PassKind pass, Target target,
                     std::string_view parser, const Facts& reflected, const Facts& observed);

// An error at "<variant>, <pass> pass, <target>" (the text could not be read
// or parsed).
Error proof_error(const LibraryVariant& variant, PassKind pass, Target target, std::string message);

// The reflection of `pass` for `target`, or an error naming what is absent.
Result<const PassReflection*> reflection_of(const LibraryVariant& variant, PassKind pass,
                                            Target target);

// One emitted file of the pass, read whole (text or SPIR-V bytes).
Result<std::string> read_pass_file(const Library& library, const LibraryVariant& variant,
                                   PassKind pass, Target target, ShaderStage stage);

// Every prover has this shape; each names the targets it proves.
using Prover = Status (*)(const Library& library, const LibraryVariant& variant, PassKind pass,
                          Target target);
Status prove_spirv(const Library& library, const LibraryVariant& variant, PassKind pass,
                   Target target);  // spirv, by SPIRV-Cross
Status prove_mesa_gl(const Library& library, const LibraryVariant& variant, PassKind pass,
                     Target target);  // glsl330, glsl450, essl300, by Mesa's driver
Status prove_glslang_essl(const Library& library, const LibraryVariant& variant, PassKind pass,
                          Target target);  // essl300, by glslang's ES 3.00 front end
Status prove_glslang_hlsl(const Library& library, const LibraryVariant& variant, PassKind pass,
                          Target target);  // hlsl_dx10, hlsl_dx9, by glslang's HLSL front end

}  // namespace penumbra::testing
