// shadow_png_check PNG [SAME_AS]: reads examples/engine-consumer's picture
// back with libpng and checks that the box's soft shadow is in it: 512 x 512
// grey, black under the box, white far from it, and on the row through the
// box a penumbra several pixels wide on the side away from the light (cast
// by the box's top), wider than where the box meets the ground. With
// SAME_AS, every pixel must also be within kSameAsLevels of that picture's:
// engine_consumer_gl's function form on its own perspective map against
// engine_consumer's query pass on Penumbra's linear map.
#include <png.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// The example's picture (examples/engine-consumer/main.cpp): x, y in
// [-2, 2] over 512 pixels, the box's footprint x in [0.4, 1.2], y in
// [-0.4, 0.4], so pixels 307..409 by 204..306.
constexpr int kSize = 512;
constexpr int kUnderBoxX = 358;
constexpr int kUnderBoxY = 256;
constexpr int kFarX = 20;  // a corner, far from the box
constexpr int kFarY = 20;
constexpr int kMinSoftEdge = 8;  // pixels of the far edge's penumbra, at least
// Two maps in different encodings round a receiver's comparison alike but
// for float rounding at a tie: a level or two of 255 at a few pixels.
constexpr int kSameAsLevels = 2;

int fail(const std::string& message) {
  std::fprintf(stderr, "shadow_png_check: %s\n", message.c_str());
  return 1;
}

// Pixels strictly between black and white on row y, from x stepping by dx
// until the row's end.
int penumbra_width(const std::vector<png_byte>& grey, int x, int y, int dx) {
  int width = 0;
  for (; x >= 0 && x < kSize; x += dx) {
    const png_byte v = grey[static_cast<std::size_t>(y) * kSize + x];
    width += v > 0 && v < 255;
  }
  return width;
}

// The 512 x 512 grey pixels of `path`, or empty with `error` set.
std::vector<png_byte> read_grey(const std::string& path, std::string& error) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0) {
    error = path + ": " + image.message;
    return {};
  }
  if (image.width != kSize || image.height != kSize) {
    png_image_free(&image);
    error = path + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
            ", not 512x512";
    return {};
  }
  image.format = PNG_FORMAT_GRAY;
  std::vector<png_byte> grey(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, grey.data(), 0, nullptr) == 0) {
    error = path + ": " + image.message;
    return {};
  }
  return grey;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) return fail("usage: shadow_png_check PNG [SAME_AS]");
  std::string error;
  const std::vector<png_byte> grey = read_grey(argv[1], error);
  if (grey.empty()) return fail(error);

  const auto at = [&](int x, int y) { return grey[static_cast<std::size_t>(y) * kSize + x]; };
  if (at(kUnderBoxX, kUnderBoxY) != 0) {
    return fail("under the box is " + std::to_string(at(kUnderBoxX, kUnderBoxY)) + ", not 0");
  }
  if (at(kFarX, kFarY) != 255) {
    return fail("far from the box is " + std::to_string(at(kFarX, kFarY)) + ", not 255");
  }
  const int far_edge = penumbra_width(grey, kUnderBoxX, kUnderBoxY, 1);
  const int near_edge = penumbra_width(grey, kUnderBoxX, kUnderBoxY, -1);
  if (far_edge < kMinSoftEdge || far_edge <= near_edge) {
    return fail("the penumbra is " + std::to_string(far_edge) +
                " pixels wide away from the light, " + std::to_string(near_edge) +
                " towards it (expected at least " + std::to_string(kMinSoftEdge) +
                ", and wider than towards the light)");
  }
  std::printf("shadow_png_check: penumbra %d pixels wide away from the light, %d towards it\n",
              far_edge, near_edge);
  if (argc == 3) {
    const std::vector<png_byte> other = read_grey(argv[2], error);
    if (other.empty()) return fail(error);
    int largest = 0;
    for (std::size_t k = 0; k < grey.size(); ++k)
      largest = std::max(largest, std::abs(grey[k] - other[k]));
    if (largest > kSameAsLevels) {
      return fail(std::string(argv[1]) + " differs from " + argv[2] + " by up to " +
                  std::to_string(largest) + " levels (allowed: " + std::to_string(kSameAsLevels) +
                  ")");
    }
    std::printf("shadow_png_check: within %d levels of %s\n", largest, argv[2]);
  }
  return 0;
}
