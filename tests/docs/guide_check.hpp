// Checks the engine guides (docs/engines/*.md) against the reflection in
// index.json: their marked bindings tables and the numbers their code
// snippets give the names of those tables.
//
// A marked table is a Markdown table between
//   <!-- reflection VARIANT PASS TARGET STAGE -->   (STAGE: vert or frag; PASS
//   may be `function`, the variant's function form)
//   <!-- end reflection -->
// Its first column is `name`; the other column headers are fields of
// reflection_rows() (`register`, `binding`, `format`, ...). Cells may be in
// backticks; `-` or an empty cell means the reflection has no such field.
// The table must list exactly the stage's rows, each with the reflection's
// values in every column it has.
//
// Code snippets (``` fences): a line that names a resource of a marked table
// (the whole word, e.g. `params_sampling`, `"ShadowParams"`) is checked for
// the numbers it gives. Each of these must be one of the named resources':
//   - HLSL registers: b#, c#, s#, t# as whole words (`register(c2)`, `// s1`);
//   - TEXCOORD# semantics;
//   - `binding = N` (GLSL layouts, VkDescriptorSetLayoutBinding),
//     `dstBinding = N` (VkWriteDescriptorSet) and `location = N`;
//   - the first argument of the calls that take a register or binding
//     number: SetVertexShaderConstantF, SetPixelShaderConstantF (c#),
//     SetTexture, SetSamplerState (s#), VSSetConstantBuffers,
//     PSSetConstantBuffers (b#), PSSetShaderResources (t#), PSSetSamplers
//     (s#), glBindTextureUnit, glBindSampler and glBindBufferBase's second
//     (binding).
// So a guide writes each such call on one line with the resource's name
// (in a comment if the call does not carry it), and writes numbers the
// engine chooses itself (GLSL 3.30 and WebGL2 texture units) as named
// constants, not literals.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/target_reflection.hpp"

namespace penumbra::testing {

// A field name (table column) to its value; a missing field is absent.
using ReflectionRow = std::map<std::string, std::string>;

// One row per resource of `stage` ("vert" or "frag"), keyed by name: the
// blocks, their members, loose uniforms, textures and Direct3D 10 sampler
// objects; the vertex inputs (vert) or the render targets, `depth_target`
// and extensions (frag). Fields: kind, name, type, register, set, binding,
// location, offset, size, registers, parameter, semantic, components, format,
// view format, comparison, filter, mip filter, address.
std::map<std::string, ReflectionRow> reflection_rows(const PassReflection& pass,
                                                     std::string_view stage);

struct GuideTable {
  std::size_t line = 0;  // of the opening marker, 1-based
  std::string variant, pass, target, stage;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct CodeLine {
  std::size_t line = 0;
  std::string text;
};

struct Guide {
  std::vector<GuideTable> tables;
  std::vector<CodeLine> code;       // every line inside ``` fences
  std::vector<std::string> errors;  // malformed markers or tables
};

Guide parse_guide(std::string_view markdown);

// The cells of a Markdown table row, trimmed and without backticks; a `-`
// cell is empty.
std::vector<std::string> split_row(std::string_view line);

// Differences between `table` and the reflection's rows for its stage.
std::vector<std::string> compare_table(const GuideTable& table, const PassReflection& pass);

// Numbers in `code` that disagree with the named resources' `rows` (the
// rows of every marked table of the guide).
std::vector<std::string> check_code(const std::vector<CodeLine>& code,
                                    const std::vector<ReflectionRow>& rows);

}  // namespace penumbra::testing
