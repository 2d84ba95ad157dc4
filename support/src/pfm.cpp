// PFM reading and writing. The whole file is read first so that every size
// in the header can be checked against the real byte count before anything
// is allocated from it.
#include "penumbra/support/pfm.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

Error bad_file(const std::filesystem::path& path, std::string message) {
  return make_error(Error::Kind::bad_input, path.string(), "not a valid PFM file: " + message);
}

std::uint32_t byteswap(std::uint32_t x) {
  return (x >> 24) | ((x >> 8) & 0xff00u) | ((x << 8) & 0xff0000u) | (x << 24);
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Splits the header into its four whitespace-separated tokens. PFM allows any
// whitespace between them but exactly one character after the scale.
class HeaderReader {
 public:
  explicit HeaderReader(std::string_view bytes) : bytes_(bytes) {}

  std::string_view next() {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    return bytes_.substr(start, pos_ - start);
  }
  // Offset of the pixel data: one whitespace character after the last token.
  std::size_t data_offset() const { return pos_ + 1; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

template <typename T>
bool parse_number(std::string_view token, T& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

Result<FloatImage> read_pfm(const std::filesystem::path& path) {
  PENUMBRA_TRY_ASSIGN(const std::string bytes, read_file(path));
  return parse_pfm(bytes, path);
}

Result<FloatImage> parse_pfm(std::string_view bytes, const std::filesystem::path& path) {
  HeaderReader header(bytes);

  const std::string_view magic = header.next();
  if (magic != "Pf" && magic != "PF") {
    return bad_file(path, "bad magic '" + std::string(magic.substr(0, 8)) +
                              "' (allowed: 'Pf' one channel, 'PF' three channels)");
  }
  const int channels = magic == "PF" ? 3 : 1;

  int width = 0;
  int height = 0;
  const std::string_view width_token = header.next();
  const std::string_view height_token = header.next();
  if (!parse_number(width_token, width) || !parse_number(height_token, height) || width <= 0 ||
      height <= 0) {
    return bad_file(path, "bad size '" + std::string(width_token) + " " +
                              std::string(height_token) + "' (need two positive integers)");
  }

  double scale = 0.0;
  const std::string_view scale_token = header.next();
  if (!parse_number(scale_token, scale) || scale == 0.0 || !std::isfinite(scale)) {
    return bad_file(path, "bad scale '" + std::string(scale_token) +
                              "' (need a non-zero number; negative means little endian)");
  }
  const bool little_endian = scale < 0.0;

  // width * height fits in 64 bits (each < 2^31); times 4 * channels it may
  // not, and a wrapped product could match a small file.
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  const std::uint64_t texel_bytes = std::uint64_t(channels) * 4;
  if (pixels > std::numeric_limits<std::uint64_t>::max() / texel_bytes) {
    return bad_file(
        path, "the size " + std::to_string(width) + "x" + std::to_string(height) + " is too large");
  }
  const std::uint64_t expected = pixels * texel_bytes;
  const std::uint64_t available =
      header.data_offset() <= bytes.size() ? bytes.size() - header.data_offset() : 0;
  if (available < expected) {
    return bad_file(path, "truncated data: " + std::to_string(width) + "x" +
                              std::to_string(height) + "x" + std::to_string(channels) +
                              " floats need " + std::to_string(expected) + " bytes, found " +
                              std::to_string(available));
  }
  if (available > expected) {
    return bad_file(path, std::to_string(available - expected) +
                              " bytes of extra data after the pixels (is the size right?)");
  }

  FloatImage image(width, height, channels);
  const char* data = bytes.data() + header.data_offset();
  const bool swap = little_endian != (std::endian::native == std::endian::little);
  for (std::size_t k = 0; k < image.data.size(); ++k) {
    std::uint32_t word = 0;
    std::memcpy(&word, data + 4 * k, 4);
    if (swap) word = byteswap(word);
    std::memcpy(&image.data[k], &word, 4);
  }
  return image;
}

Status write_pfm(const std::filesystem::path& path, const FloatImage& image) {
  if (image.channels != 1 && image.channels != 3) {
    return make_error(Error::Kind::bad_input, path.string(),
                      "PFM holds 1 or 3 channels, the image has " + std::to_string(image.channels));
  }
  if (image.width <= 0 || image.height <= 0 ||
      image.data.size() != image.pixel_count() * image.channels) {
    return make_error(Error::Kind::internal, path.string(), "image size and data do not match");
  }
  std::ostringstream out;
  out << (image.channels == 3 ? "PF" : "Pf") << '\n'
      << image.width << ' ' << image.height << '\n'
      << "-1.0\n";
  std::string bytes = std::move(out).str();
  const std::size_t header_size = bytes.size();
  bytes.resize(header_size + 4 * image.data.size());
  const bool swap = std::endian::native != std::endian::little;
  for (std::size_t k = 0; k < image.data.size(); ++k) {
    std::uint32_t word = 0;
    std::memcpy(&word, &image.data[k], 4);
    if (swap) word = byteswap(word);
    std::memcpy(bytes.data() + header_size + 4 * k, &word, 4);
  }
  return write_file_atomic(path, bytes);
}

}  // namespace penumbra
