// 8-bit RGB pictures and their PNG files (libpng's simplified API).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::report {

struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;  // linear, in [0, 1]
};

// Row 0 at the top, 3 bytes per pixel, sRGB-encoded.
struct Picture {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  Picture() = default;
  Picture(int w, int h) : width(w), height(h), rgb(std::size_t(w) * h * 3, 0) {}
  void set(int x, int y, Rgb linear);  // stores the sRGB encoding of `linear`
};

Status write_png(const std::filesystem::path& path, const Picture& picture);

}  // namespace penumbra::report
