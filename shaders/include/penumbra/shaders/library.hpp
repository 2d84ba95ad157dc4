// Shaders embedded in a program by `penumbra embed` (docs/embedding.md):
// every pass of every variant of a built library, for each of its targets,
// with the pass's reflection, found by technique and keys. Needs only the
// model types: no compiler, no graphics API.
#pragma once

#include <cstdint>
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

class Library {
 public:
  // `blob`: the pieces of the generated blob, in order (each piece stays
  // under every compiler's string literal limit); `programs` index it.
  Library(std::span<const std::string_view> blob, std::span<const EmbeddedProgram> programs);
  // Programs point into the library's own copy of the blob.
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;

  // The program of the variant `technique` with `keys` makes
  // (variant_name()), or nullptr when the library does not hold it.
  const Program* find(Technique technique, const VariantKeys& keys, Target target,
                      PassKind pass = PassKind::query) const;
  // The same by the variant's name.
  const Program* find(std::string_view variant, Target target,
                      PassKind pass = PassKind::query) const;

  // Every program, ordered by variant name, target and pass.
  std::span<const Program> programs() const { return programs_; }

 private:
  std::string blob_;                               // the pieces joined
  std::vector<std::vector<std::uint32_t>> words_;  // SPIR-V, copied out aligned
  std::vector<Program> programs_;
};

}  // namespace penumbra::shaders
