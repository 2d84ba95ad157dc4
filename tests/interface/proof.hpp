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

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "penumbra/library/library.hpp"
#include "penumbra/library/pass_files.hpp"

namespace penumbra::testing {

// Entry ("frag uniform params.light", prefixed by stage_key()) -> what the
// side says of it.
using Facts = std::map<std::string, std::string>;

// How a parser states bindings and members, so that the reflection is
// written the way that parser writes what it sees.
struct FactStyle {
  bool with_set = false;      // SPIR-V: "set S, binding B"
  bool member_sizes = false;  // SPIR-V: a member's byte size after its offset
  // What the parser reports where the text gives no binding: OpenGL's
  // glGetUniformiv and GL_UNIFORM_BLOCK_BINDING say 0; else "-".
  std::optional<std::uint32_t> unset_binding;
};

// "set 0, binding 2", "binding 2" or "binding -".
std::string slot_text(const FactStyle& style, std::optional<std::uint32_t> set,
                      std::optional<std::uint32_t> binding);
// "sampler2DShadow, comparison".
std::string texture_text(std::string_view type, bool comparison);
// "vec4 at 16" (with sizes: "vec4 at 16, 16 bytes").
std::string member_text(const FactStyle& style, std::string_view type,
                        std::optional<std::uint32_t> offset, std::uint32_t size);
// "location 0, 2 components, GL_FLOAT".
std::string input_text(std::optional<std::uint32_t> location, std::uint32_t components,
                       std::string_view format);

// The reflection of a GLSL-family or SPIR-V target (blocks, uniforms,
// textures, vertex inputs and fragment outputs) written in `style`.
Facts reflected_facts(const PassReflection& pass, const FactStyle& style);

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
