#include "png_file.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>

#include "penumbra/support/file.hpp"

namespace penumbra::report {
namespace {

std::uint8_t encode(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

}  // namespace

void Picture::set(int x, int y, Rgb linear) {
  const std::size_t at = (std::size_t(y) * width + x) * 3;
  rgb[at] = encode(linear.r);
  rgb[at + 1] = encode(linear.g);
  rgb[at + 2] = encode(linear.b);
}

Status write_png(const std::filesystem::path& path, const Picture& picture) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(picture.width);
  image.height = static_cast<png_uint_32>(picture.height);
  image.format = PNG_FORMAT_RGB;
  // Encoded in memory, then written by write_file(): libpng's own file
  // writer loses the system's reason when the file cannot be created.
  png_alloc_size_t size = 0;
  if (png_image_write_to_memory(&image, nullptr, &size, 0, picture.rgb.data(), 0, nullptr) != 0) {
    std::string bytes(size, '\0');
    if (png_image_write_to_memory(&image, bytes.data(), &size, 0, picture.rgb.data(), 0, nullptr) !=
        0) {
      return write_file(path, std::string_view(bytes).substr(0, size));
    }
  }
  const std::string why = image.message;
  png_image_free(&image);
  return make_error(Error::Kind::io, path.string(), "cannot encode the PNG: " + why);
}

}  // namespace penumbra::report
