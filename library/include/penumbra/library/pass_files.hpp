// Finding one pass of a library variant: its files, where each stage lives
// on disk, its reflection record, and a stage's bytes read whole.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/library/library.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// index.json's passes.<pass>.<target>, or an error naming the variant.
Result<const PassFiles*> pass_files(const LibraryVariant& variant, PassKind pass, Target target);

// Where one stage of a pass lives in the library.
Result<std::filesystem::path> pass_stage_path(const Library& library, const LibraryVariant& variant,
                                              PassKind pass, Target target, ShaderStage stage);

// index.json's reflection.<pass>.<target>: what an engine binds.
Result<PassReflection> pass_reflection(const LibraryVariant& variant, PassKind pass, Target target);

// The emitted text (or .spv bytes) of one stage of a pass.
Result<std::string> read_pass_file(const Library& library, const LibraryVariant& variant,
                                   PassKind pass, Target target, ShaderStage stage);

}  // namespace penumbra
