// Reading and writing a whole file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra {

// The file's bytes, unchanged (binary mode). An Error of kind io, located at
// `path`, when the file cannot be opened or read (a directory, an empty
// name), its message ending in the system's reason ("No such file or
// directory").
Result<std::string> read_file(const std::filesystem::path& path);

// Creates or truncates `path` and writes `bytes`. An Error of kind io,
// located at `path`, naming what failed and the system's reason ("cannot
// create the file: Permission denied"); a file left half written is removed.
Status write_file(const std::filesystem::path& path, std::string_view bytes);

}  // namespace penumbra
