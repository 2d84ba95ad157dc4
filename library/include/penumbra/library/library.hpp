// A built shader library read back from OUT/index.json: what an engine or a
// tool needs to find, bind and run its files, with no shader compiler (this
// layer links none of glslang, SPIRV-Tools or SPIRV-Cross).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// A Direct3D bytecode file compiled from a stage's HLSL text.
struct BytecodeFile {
  std::string path;        // relative to the library root, beside the text
  std::string profile;     // "vs_3_0", "ps_3_0", "vs_4_0" or "ps_4_0"
  std::uint64_t size = 0;  // in bytes
  // Shader Model 3: the instruction slots of its disassembly; else 0.
  int instruction_slots = 0;
};

struct PassFiles {
  std::string vert;  // relative to the library root
  std::string frag;
  // Direct3D bytecode of each stage: the HLSL targets built with an HLSL compiler.
  std::optional<BytecodeFile> vert_bytecode;
  std::optional<BytecodeFile> frag_bytecode;
};

// A variant's function form for one target (docs/function-form.md).
struct FunctionForm {
  std::string file;           // the includable source, relative to the library root
  PassReflection reflection;  // its bindings, signature and extensions
};

struct LibraryVariant {
  Variant variant;  // keys, disks (the baked values) and targets
  std::map<PassKind, std::map<Target, PassFiles>> passes;
  // What each pass's files declare, per target (what engines bind by).
  std::map<PassKind, std::map<Target, PassReflection>> reflection;
  std::map<Target, FunctionForm> function;  // the text targets, for techniques that have one
};

// index.json's `schema`: 4 since a constant texture's contents name the
// variant's disk, so records that differ only in their disks are one (3 kept
// the texels in a `texture_contents` table, one record per disk); since 3
// identical reflection records and disks are stored once, in the top-level
// `reflections` and `disks` tables, and each variant refers to them by
// position (2 repeated them in every variant).
inline constexpr int kIndexSchema = 4;

struct Library {
  std::filesystem::path root;
  std::string generator;
  std::vector<LibraryVariant> variants;

  const LibraryVariant* find(std::string_view name) const;
};

// Reads OUT/index.json and resolves each variant's references into the shared
// tables, so every LibraryVariant holds its own disks and reflection records;
// errors (a schema other than kIndexSchema, a reference out of range) name the
// file and the JSON path.
Result<Library> load_library(const std::filesystem::path& root);
// The same for index.json's text, as if read from `root`/index.json.
Result<Library> parse_library(std::string_view text, const std::filesystem::path& root);

// Reads a .spv file into words.
Result<std::vector<std::uint32_t>> read_spirv_file(const std::filesystem::path& path);

}  // namespace penumbra
