// `penumbra embed`: a built library as C++ sources a program compiles in,
// read back through penumbra::shaders::Library (docs/embedding.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "penumbra/compiler/library.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct EmbedOptions {
  std::string name;  // C++ namespace and header folder: <name>/shaders.hpp
};

struct EmbedSummary {
  std::size_t programs = 0;        // passes x targets embedded
  std::uint64_t blob_bytes = 0;    // distinct contents, shared ones once
  std::uint64_t source_bytes = 0;  // what the files take in the library
};

// Writes `out`/include/<name>/shaders.hpp, which declares <name>::library()
// and <name>::find() (rewritten only when its text changes), and
// `out`/<name>_shaders.cpp, which holds every file of `library` (identical
// contents once) and the table. `name` must be a C++ identifier.
Result<EmbedSummary> embed_library(const Library& library, const std::filesystem::path& out,
                                   const EmbedOptions& options);

}  // namespace penumbra
