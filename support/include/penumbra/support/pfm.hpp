// PFM image files: "Pf" (one channel) and "PF" (three). The first stored row
// is row j = 0, as docs/shader-interface.md fixes (no vertical flip on read or write).
#pragma once

#include <filesystem>
#include <string_view>

#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// Reads a Pf or PF file; both byte orders (negative scale = little endian).
Result<FloatImage> read_pfm(const std::filesystem::path& path);
// The same for a file's bytes; `path` names it in messages.
Result<FloatImage> parse_pfm(std::string_view bytes, const std::filesystem::path& path);

// Writes a Pf (channels == 1) or PF (channels == 3) file, little endian,
// atomically (a temporary file renamed into place).
Status write_pfm(const std::filesystem::path& path, const FloatImage& image);

}  // namespace penumbra
