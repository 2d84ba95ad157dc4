// Reading a whole file.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra {

// The file's bytes, unchanged (binary mode). An Error of kind io, located at
// `path`, when the file cannot be opened or read (a directory, an empty
// name), its message ending in the system's reason ("No such file or
// directory").
Result<std::string> read_file(const std::filesystem::path& path);

}  // namespace penumbra
