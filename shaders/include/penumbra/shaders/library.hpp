// Shaders embedded in a program by `penumbra embed` (docs/embedding.md):
// every pass of every variant of a built library, for each of its targets,
// with the pass's reflection, and each variant's function forms
// (docs/function-form.md), found by technique and keys. Needs only the
// model types: no compiler, no graphics API.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/model/pass.hpp"

namespace penumbra::shaders {

// One stage of a program.
struct StageCode {
  std::string_view text;                   // GLSL or HLSL; empty for spirv
  std::span<const std::uint32_t> spirv;    // the spirv target's words; empty otherwise
  std::span<const std::uint8_t> bytecode;  // .d3dbc / .dxbc where the library has bytecode
  std::string_view profile;                // the bytecode's profile ("ps_3_0"), or empty
};

// One pass of one variant for one target.
struct Program {
  std::string_view variant;  // the variant's name, e.g. "pcss_b16_p16_poisson"
  Target target = Target::spirv;
  PassKind pass = PassKind::query;
  StageCode vertex;
  StageCode fragment;
  // The reflection record index.json's `reflection.<pass>.<target>` points
  // at, as JSON text: what an engine binds by (docs/shader-interface.md).
  std::string_view reflection;
};

// One variant's function form for one text target: the includable source
// declaring penumbra_visibility().
struct Function {
  std::string_view variant;  // the variant's name
  Target target = Target::glsl450;
  std::string_view text;  // the file index.json's `function.<target>.file` names
  // Its reflection record (`function.<target>.reflection`), as JSON text:
  // the names to bind, `signature` and `extensions`.
  std::string_view reflection;
};

// A part of the generated blob.
struct BlobRange {
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
};

// One program as `penumbra embed` writes it: ranges of the blob.
struct EmbeddedProgram {
  const char* variant;
  Target target;
  PassKind pass;
  BlobRange vertex;  // text, or the SPIR-V bytes for spirv
  BlobRange fragment;
  BlobRange vertex_bytecode;  // size 0: none
  BlobRange fragment_bytecode;
  const char* vertex_profile;  // "" without bytecode
  const char* fragment_profile;
  BlobRange reflection;
};

// One variant as `penumbra embed` writes it: the forms it was built in
// (index.json's "forms"), bit Form set for each.
struct EmbeddedVariant {
  const char* name;
  unsigned forms;
};

// One function form as `penumbra embed` writes it.
struct EmbeddedFunction {
  const char* variant;
  Target target;
  BlobRange text;
  BlobRange reflection;
};

// One object's share of the generated shaders (`penumbra embed --part`
// writes one per group): the pieces of its blob, in order, each under every
// compiler's string literal limit, its programs, which index that blob,
// ordered by variant name, target and pass, and its function forms,
// ordered by variant name and target, and its variants, ordered by name.
struct EmbeddedPart {
  std::span<const std::string_view> blob;
  std::span<const EmbeddedProgram> programs;
  std::span<const EmbeddedFunction> functions = {};
  std::span<const EmbeddedVariant> variants = {};
};

// The lookup over every part. Constructing it copies nothing: a part's
// blob is joined (and its SPIR-V copied into aligned words) the first time
// one of its programs is found, once, safely from any thread.
class Library {
 public:
  // `parts` must outlive the library (the generated sources keep them static).
  explicit Library(std::span<const EmbeddedPart> parts);
  ~Library();
  // Programs point into the library's own copies of the parts' blobs.
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;

  // The program of the variant `technique` with `keys` makes
  // (variant_name()), or nullptr when the library does not hold it.
  const Program* find(Technique technique, const VariantKeys& keys, Target target,
                      PassKind pass = PassKind::query) const;
  // The same by the variant's name.
  const Program* find(std::string_view variant, Target target,
                      PassKind pass = PassKind::query) const;

  // The function form of the variant `technique` with `keys` makes for
  // `target`, or nullptr when the library does not hold one.
  const Function* find_function(Technique technique, const VariantKeys& keys, Target target) const;
  // The same by the variant's name.
  const Function* find_function(std::string_view variant, Target target) const;

  // The forms the variant was built in, in kAllForms order (`penumbra build
  // --form`, the manifest's "forms"); empty when the library does not hold it.
  std::vector<Form> forms(std::string_view variant) const;
  // Why find() finds no program, for a message: the variant is not in the
  // library, was built without the form the pass belongs to (naming the
  // forms it has), or has no such pass for `target`. Empty when it is found.
  std::string why_not_found(std::string_view variant, Target target,
                            PassKind pass = PassKind::query) const;
  // The same for find_function().
  std::string why_no_function(std::string_view variant, Target target) const;

  // How many programs the library holds, without building any.
  std::size_t size() const;
  // Every program, ordered by variant name, target and pass; builds every
  // part.
  std::vector<const Program*> programs() const;
  // Every function form, ordered by variant name and target; builds every
  // part.
  std::vector<const Function*> functions() const;

 private:
  struct Built;  // one part's joined blob, words, programs and function forms

  const Built& built(std::size_t part) const;

  std::span<const EmbeddedPart> parts_;
  std::unique_ptr<Built[]> built_;
};

}  // namespace penumbra::shaders
