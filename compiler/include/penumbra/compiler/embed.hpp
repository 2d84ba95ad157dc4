// `penumbra embed`: a built library as C++ sources a program compiles in,
// read back through penumbra::shaders::Library (docs/embedding.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "penumbra/library/library.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct EmbedOptions {
  std::string name;  // C++ namespace and header folder: <name>/shaders.hpp
  // 0: one source holding every program and <name>::library(). I > 0: part
  // I of a library split over objects (`embed_part_index` joins them).
  std::size_t part = 0;
};

struct EmbedSummary {
  std::size_t programs = 0;        // passes x targets embedded
  std::size_t functions = 0;       // function forms x targets embedded
  std::uint64_t blob_bytes = 0;    // distinct contents, shared ones once
  std::uint64_t source_bytes = 0;  // what the files take in the library
};

// Without a part: writes `out`/include/<name>/shaders.hpp, which declares
// <name>::library() and <name>::find(), and `out`/<name>_shaders.cpp, which
// holds every file of `library` (identical contents once), the table and
// library(). With part I: writes only `out`/<name>_shaders_I.cpp, the same
// for `library`'s programs as <name>::parts::part_I. Each file is rewritten
// only when its text changes. `name` must be a C++ identifier.
Result<EmbedSummary> embed_library(const Library& library, const std::filesystem::path& out,
                                   const EmbedOptions& options);

// Writes the header and `out`/<name>_shaders.cpp, whose library() joins the
// parts 1..`parts` embed_library() wrote: one object each, so that a large
// library compiles in pieces and in parallel.
Status embed_part_index(const std::filesystem::path& out, const std::string& name,
                        std::size_t parts);

}  // namespace penumbra
